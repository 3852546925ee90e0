#include "tables/ltc/ltc.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace glintlab {

Ltc::Ltc(const glm::dmat3& m) : m_(m) {
  const double det = glm::determinant(m);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) throw std::invalid_argument("LTC: the matrix M is singular");
  m_inv_ = glm::inverse(m);
  det_inv_abs_ = 1.0 / std::abs(det);
}

Ltc Ltc::from_inverse(const glm::dmat3& m_inverse) {
  const double det = glm::determinant(m_inverse);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) throw std::invalid_argument("LTC: the matrix M^-1 is singular");
  return Ltc(glm::inverse(m_inverse));
}

double Ltc::density(const glm::dvec3& w) const {
  const glm::dvec3 wo = m_inv_ * w;
  if (!(wo.z > 0.0)) return 0.0;
  // D_cos(wo / |wo|) |det M^-1| / |wo|^3 with D_cos(x) = x.z / pi: wo.z |det M^-1| / (pi |wo|^4).
  const double length2 = glm::dot(wo, wo);
  return wo.z / (std::numbers::pi * length2 * length2) * det_inv_abs_;
}

double Ltc::density_of_cosine_direction(const glm::dvec3& w_o) const {
  if (!(w_o.z > 0.0)) return 0.0;
  const double length = glm::length(m_ * w_o);
  return w_o.z / std::numbers::pi * det_inv_abs_ * length * length * length;
}

glm::dvec3 Ltc::sample(glm::dvec2 u) const { return glm::normalize(m_ * sample_cosine(u)); }

glm::dvec3 sample_cosine(glm::dvec2 u) {
  const double r = std::sqrt(u.x), phi = 2.0 * std::numbers::pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u.x))};
}

std::vector<glm::dvec3> clip_to_upper_half_space(std::span<const glm::dvec3> polygon) {
  std::vector<glm::dvec3> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3& a = polygon[i];
    const glm::dvec3& b = polygon[(i + 1) % n];
    if (a.z >= 0.0) out.push_back(a);
    if ((a.z >= 0.0) != (b.z >= 0.0)) {  // the edge crosses z = 0: add the crossing
      const double t = a.z / (a.z - b.z);
      glm::dvec3 crossing = a + t * (b - a);
      crossing.z = 0.0;
      out.push_back(crossing);
    }
  }
  return out;
}

double clipped_polygon_form_factor(std::span<const glm::dvec3> polygon) {
  const std::vector<glm::dvec3> clipped = clip_to_upper_half_space(polygon);
  const std::size_t n = clipped.size();
  if (n < 3) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 a = glm::normalize(clipped[i]);
    const glm::dvec3 b = glm::normalize(clipped[(i + 1) % n]);
    const glm::dvec3 c = glm::cross(a, b);
    const double sin_angle = glm::length(c);
    if (!(sin_angle > 0.0)) continue;  // a degenerate edge subtends nothing
    const double angle = std::atan2(sin_angle, glm::dot(a, b));  // acos(a.b), accurate near 0 and pi
    sum += angle * c.z / sin_angle;
  }
  return sum / (2.0 * std::numbers::pi);
}

double ltc_polygon_integral(const Ltc& ltc, std::span<const glm::dvec3> polygon, bool clip_surface_horizon) {
  std::vector<glm::dvec3> vertices = clip_surface_horizon ? clip_to_upper_half_space(polygon)
                                                          : std::vector<glm::dvec3>(polygon.begin(), polygon.end());
  for (auto& v : vertices) v = ltc.inverse() * v;
  // A linear map with negative determinant mirrors the winding; the integral keeps the polygon's.
  const double sign = glm::determinant(ltc.inverse()) < 0.0 ? -1.0 : 1.0;
  return sign * clipped_polygon_form_factor(vertices);
}

double ltc_disk_integral(const Ltc& ltc, const glm::dvec3& centre, const glm::dvec3& normal, double radius,
                         int segments, bool clip_surface_horizon) {
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(n, helper)), e2 = glm::cross(n, e1);
  // A regular polygon of the disk's area: its circumradius is r sqrt(t / sin t), t = 2 pi / segments.
  const double step = 2.0 * std::numbers::pi / segments;
  const double circumradius = radius * std::sqrt(step / std::sin(step));
  std::vector<glm::dvec3> polygon(static_cast<std::size_t>(segments));
  for (int k = 0; k < segments; ++k)
    polygon[static_cast<std::size_t>(k)] = centre + circumradius * (std::cos(k * step) * e1 + std::sin(k * step) * e2);
  return std::abs(ltc_polygon_integral(ltc, polygon, clip_surface_horizon));
}

double ltc_sphere_integral(const Ltc& ltc, const glm::dvec3& centre, double radius, int segments,
                           bool clip_surface_horizon) {
  // The cap of angular radius sigma = asin(r / d) about c / d: on the unit sphere its boundary is
  // the circle of centre cos(sigma) c / d and radius sin(sigma) in the plane normal to c.
  const double d = glm::length(centre);
  if (!(radius < d)) throw std::invalid_argument("LTC: the shading point is inside the sphere");
  const double sin_sigma = radius / d, cos_sigma = std::sqrt(1.0 - sin_sigma * sin_sigma);
  const glm::dvec3 axis = centre / d;
  return ltc_disk_integral(ltc, cos_sigma * axis, axis, sin_sigma, segments, clip_surface_horizon);
}

}  // namespace glintlab
