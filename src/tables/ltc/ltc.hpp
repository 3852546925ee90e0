#pragma once
// A linearly transformed cosine (Heitz, Dupuy, Hill, Neubelt 2016, "Real-time polygonal-light
// shading with linearly transformed cosines"): the clamped cosine D_cos(w) = max(0, w.z) / pi
// whose directions are transformed by a 3x3 matrix M. In the shading frame (z = normal, x along
// the view's tangent projection),
//
//   D_o(w) = D_cos(w_o) |det M^-1| / |M^-1 w|^3,   w_o = M^-1 w / |M^-1 w|      (eq. 1-3),
//
// it integrates to 1 over the sphere, and its integral over a polygon P is the clamped-cosine
// integral (form factor) of the polygon M^-1 P (eq. 4), which has a closed form (eq. 11).
// This is the CPU reference the GLSL runtime is compared with; src/tables/ltc/ltc_fit.hpp fits M.
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace glintlab {

class Ltc {
 public:
  Ltc() = default;
  /// The distribution of M; throws std::invalid_argument if M is singular.
  explicit Ltc(const glm::dmat3& m);
  /// The distribution whose inverse matrix is `m_inverse` (what the tables store).
  static Ltc from_inverse(const glm::dmat3& m_inverse);

  [[nodiscard]] const glm::dmat3& matrix() const { return m_; }
  [[nodiscard]] const glm::dmat3& inverse() const { return m_inv_; }
  /// D_o(w) for a unit direction w (eq. 3); zero where M^-1 w is below the horizon.
  [[nodiscard]] double density(const glm::dvec3& w) const;
  /// D_o(M w_o / |M w_o|) for a unit direction w_o of the cosine's space: the density at the
  /// image of w_o without inverting anything (|M^-1 w| = 1 / |M w_o|).
  [[nodiscard]] double density_of_cosine_direction(const glm::dvec3& w_o) const;
  /// A direction distributed as D_o: a cosine-distributed direction transformed by M (eq. 2), for
  /// u in [0, 1)^2.
  [[nodiscard]] glm::dvec3 sample(glm::dvec2 u) const;

 private:
  glm::dmat3 m_{1.0}, m_inv_{1.0};
  double det_inv_abs_ = 1.0;
};

/// A cosine-distributed unit direction about +z (Malley's method: a uniform disk point lifted),
/// for u in [0, 1)^2.
glm::dvec3 sample_cosine(glm::dvec2 u);

/// The polygon clipped to the upper half space z >= 0 (Sutherland-Hodgman against one plane):
/// at most one vertex more than it had.
std::vector<glm::dvec3> clip_to_upper_half_space(std::span<const glm::dvec3> polygon);

/// The form factor of a polygon seen from the origin, i.e. the integral of D_cos over the
/// directions it subtends, after clipping it to z >= 0 (eq. 11 of Heitz et al. 2016; Lambert's
/// formula): sum over edges of acos(v_i . v_j) normalize(v_i x v_j).z / (2 pi) with v the unit
/// vertex directions. Positive when the vertices turn counter-clockwise about +z (seen from above,
/// i.e. clockwise seen from the origin), negative for the opposite winding.
double clipped_polygon_form_factor(std::span<const glm::dvec3> polygon);

/// The integral of D_o over a polygon (vertices relative to the shading point, in the shading
/// frame), signed by the winding as above: the form factor of M^-1 P clipped to the cosine's
/// horizon (eq. 4). With `clip_surface_horizon` the polygon is first clipped to the surface's
/// horizon z >= 0, where the fitted lobes live (the LTC may reach below it).
double ltc_polygon_integral(const Ltc& ltc, std::span<const glm::dvec3> polygon, bool clip_surface_horizon = true);

/// The integral of D_o over a disk (centre and unit normal relative to the shading point, radius),
/// either side facing: the polygon integral of a regular polygon of `segments` vertices with the
/// disk's area (relative error ~ (2 pi / segments)^4). A reference for the GLSL's closed-form disk
/// (Heitz & Hill 2017), not a fast path.
double ltc_disk_integral(const Ltc& ltc, const glm::dvec3& centre, const glm::dvec3& normal, double radius,
                         int segments = 1024, bool clip_surface_horizon = true);
/// The integral of D_o over the directions a sphere subtends (centre relative to the shading point,
/// radius < |centre|): the disk of the cap's boundary circle, as ltc_disk_integral.
double ltc_sphere_integral(const Ltc& ltc, const glm::dvec3& centre, double radius, int segments = 1024,
                           bool clip_surface_horizon = true);

}  // namespace glintlab
