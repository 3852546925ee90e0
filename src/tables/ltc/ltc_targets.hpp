#pragma once
// The lobes the LTC tables are fitted to (src/tables/ltc/ltc_fit.hpp), in the shading frame (z = normal,
// view v = (sin t, 0, cos t)), for the isotropic GGX distribution of roughness alpha
// (Trowbridge-Reitz; Walter et al. 2007):
//   ggx: f(l) cos = D(h) G2(v, l) / (4 v.z), height-correlated Smith G2 = 1 / (1 + Lambda(v) +
//        Lambda(l)) (Heitz 2014, eq. 99), with h = normalize(v + l): the specular BRDF times the
//        cosine, Fresnel 1;
//   ndf: D(h) / (4 v.h): the density of l when h follows D, with no shadowing and no cosine: what
//        glint counting integrates over a light (Kneiphof & Klein 2024, sec. 4).
// Both are zero for l.z <= 0. Each has an importance sampler of its own with its pdf, which the
// fitter's multiple importance sampling needs.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace glintlab {

enum class LtcTargetKind { Ggx, Ndf };

/// D(h) of isotropic GGX, for a unit h with h.z > 0 (0 otherwise).
double ggx_ndf(const glm::dvec3& h, double alpha);
/// Smith's Lambda of isotropic GGX for a unit direction w with w.z > 0.
double ggx_lambda(const glm::dvec3& w, double alpha);
/// The integral of D over the hemisphere of normals without the cosine, in closed form:
/// 1 + a^2 ln((1 + sqrt(1 - a^2)) / a) / sqrt(1 - a^2) (1 at a = 1). The normalisation of
/// glint counting's probability (Kneiphof & Klein 2024, eq. 7).
double ggx_total_ndf(double alpha);
/// The mass of D (no cosine) over the cone of normals with tan(theta_h) <= tan_theta: the CDF
/// behind sample_ggx_ndf (ggx_ndf_cone_mass(inf) = ggx_total_ndf).
double ggx_ndf_cone_mass(double tan_theta, double alpha);
/// A normal distributed as D(h) / ggx_total_ndf (no cosine), for u in [0, 1)^2: inverts the cone
/// mass in theta by safeguarded Newton steps.
glm::dvec3 sample_ggx_ndf(glm::dvec2 u, double alpha);
/// A normal distributed as the visible normals D_v(h) = G1(v) max(0, v.h) D(h) / v.z (Heitz 2018,
/// "Sampling the GGX distribution of visible normals").
glm::dvec3 sample_ggx_visible_normal(const glm::dvec3& v, glm::dvec2 u, double alpha);

/// The integral of the ndf lobe D(h) / (4 v.h) over l.z > 0 for cos(theta_v) = cos_theta: the D-mass
/// of the normals that reflect v above the horizon. For the normals of azimuth phi (about v's
/// plane) these are theta_h < pi/4 + atan(tan(theta_v) cos(phi)) / 2, so it is the mean over phi
/// of ggx_ndf_cone_mass there (midpoint rule in phi; the integrand is smooth).
double ggx_ndf_lobe_magnitude(double alpha, double cos_theta);

/// A lobe's value at a direction and the pdf of its sampler there (both per unit solid angle).
struct LobeSample {
  double value = 0.0;
  double pdf = 0.0;
};

class LtcTarget {
 public:
  /// The lobe for roughness alpha and the view with cos(theta_v) = cos_theta (0 < cos_theta <= 1).
  LtcTarget(LtcTargetKind kind, double alpha, double cos_theta);

  [[nodiscard]] LtcTargetKind kind() const { return kind_; }
  [[nodiscard]] double alpha() const { return alpha_; }
  [[nodiscard]] const glm::dvec3& view() const { return v_; }
  /// The lobe and its sampler's pdf at a unit direction l.
  [[nodiscard]] LobeSample evaluate(const glm::dvec3& l) const;
  /// The sampler's half vector: visible normals for ggx, D itself for ndf (independent of the view,
  /// so the fitter may reuse them along a roughness).
  [[nodiscard]] glm::dvec3 sample_half_vector(glm::dvec2 u) const;
  /// The sampled direction of a half vector: v reflected about h (may lie below the horizon, where
  /// the lobe is zero).
  [[nodiscard]] glm::dvec3 reflect_view(const glm::dvec3& h) const;

 private:
  LtcTargetKind kind_;
  double alpha_;
  glm::dvec3 v_;
  double lambda_v_ = 0.0, g1_v_ = 1.0, total_ndf_ = 1.0;
};

}  // namespace glintlab
