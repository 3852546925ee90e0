#include "tables/ltc/ltc_targets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// atanh(sqrt(k) y) / sqrt(k) for 0 <= k < 1, its limit y at k = 0.
double atanh_over_root(double k, double y) {
  if (k < 1e-12) return y;
  const double r = std::sqrt(k);
  return std::atanh(r * y) / r;
}

}  // namespace

double ggx_ndf(const glm::dvec3& h, double alpha) {
  if (!(h.z > 0.0)) return 0.0;
  // alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2), with 1 - cos^2 = x^2 + y^2 (no cancellation
  // near the pole, where tiny alphas put all of D).
  const double a2 = alpha * alpha;
  const double d = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
  return a2 / (kPi * d * d);
}

double ggx_lambda(const glm::dvec3& w, double alpha) {
  const double sin2 = w.x * w.x + w.y * w.y, cos2 = w.z * w.z;
  return 0.5 * (std::sqrt(1.0 + alpha * alpha * sin2 / cos2) - 1.0);
}

double ggx_total_ndf(double alpha) {
  // 1 + a^2 atanh(sqrt(k)) / sqrt(k) with k = 1 - a^2: the same; 2 at a = 1, where D = 1/pi.
  const double k = 1.0 - alpha * alpha;
  return 1.0 + alpha * alpha * atanh_over_root(k, 1.0);
}

double ggx_ndf_cone_mass(double tan_theta, double alpha) {
  // 2 pi int_0^theta D sin = 2 a^2 int_u^1 dc / (1 - k c^2)^2 with k = 1 - a^2, c = cos:
  //   x^2 / (1 + x^2) (1 - a^2 u / (1 + u)) + a^2 atanh(sqrt(k) (1 - u) / (1 - k u)) / sqrt(k),
  // x = tan / a, written so that neither term cancels for tiny alphas.
  if (std::isinf(tan_theta)) return ggx_total_ndf(alpha);
  const double a2 = alpha * alpha, k = 1.0 - a2;
  const double u = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
  const double x2 = tan_theta * tan_theta / a2;
  const double one_minus_u = tan_theta * tan_theta * u * u / (1.0 + u);
  return x2 / (1.0 + x2) * (1.0 - a2 * u / (1.0 + u)) + a2 * atanh_over_root(k, one_minus_u / (one_minus_u + a2 * u));
}

double ggx_ndf_lobe_magnitude(double alpha, double cos_theta) {
  // l.z = 2 (v.h) h.z - v.z = 0 <=> sin(theta_v) cos(phi) sin(2 theta_h) + cos(theta_v) cos(2 theta_h) = 0.
  const double tan_v = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)) / cos_theta;
  constexpr int kSteps = 1024;  // over phi in [0, pi]: the lobe is symmetric about v's plane
  double sum = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    const double phi = kPi * (k + 0.5) / kSteps;
    const double theta_max = 0.25 * kPi + 0.5 * std::atan(tan_v * std::cos(phi));
    sum += ggx_ndf_cone_mass(std::tan(theta_max), alpha);
  }
  return sum / kSteps;
}

glm::dvec3 sample_ggx_ndf(glm::dvec2 u, double alpha) {
  const double target = u.x * ggx_total_ndf(alpha);
  // Newton on theta in [0, pi/2], d mass / d theta = 2 pi D(theta) sin(theta), kept in a bracket.
  double lo = 0.0, hi = 0.5 * kPi;
  double theta = std::atan(alpha * std::sqrt(u.x / std::max(1.0 - u.x, 1e-300)));  // the cosine-weighted guess
  for (int i = 0; i < 60; ++i) {
    const double t = std::tan(theta);
    const double f = ggx_ndf_cone_mass(t, alpha) - target;
    if (f > 0.0) hi = theta;
    else lo = theta;
    const double s = std::sin(theta), c = std::cos(theta);
    const double derivative = 2.0 * kPi * ggx_ndf({s, 0.0, c}, alpha) * s;
    double next = derivative > 0.0 ? theta - f / derivative : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - theta) < 1e-13 * std::max(theta, 1e-12)) {
      theta = next;
      break;
    }
    theta = next;
  }
  const double phi = 2.0 * kPi * u.y, s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

glm::dvec3 sample_ggx_visible_normal(const glm::dvec3& v, glm::dvec2 u, double alpha) {
  // Heitz 2018, listing 1: the hemisphere of the stretched view, its projected disk sampled with
  // the visible half warped, unstretched.
  const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
  const double length2 = vh.x * vh.x + vh.y * vh.y;
  const glm::dvec3 t1 = length2 > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(length2) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 t2 = glm::cross(vh, t1);
  const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1.0 + vh.z);
  const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
  const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
}

LtcTarget::LtcTarget(LtcTargetKind kind, double alpha, double cos_theta) : kind_(kind), alpha_(alpha) {
  if (!(alpha > 0.0 && alpha <= 1.0)) throw std::invalid_argument("LTC target: alpha must lie in (0, 1]");
  if (!(cos_theta > 0.0 && cos_theta <= 1.0)) throw std::invalid_argument("LTC target: cos(theta_v) must lie in (0, 1]");
  v_ = {std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), 0.0, cos_theta};
  lambda_v_ = ggx_lambda(v_, alpha);
  g1_v_ = 1.0 / (1.0 + lambda_v_);
  total_ndf_ = ggx_total_ndf(alpha);
}

LobeSample LtcTarget::evaluate(const glm::dvec3& l) const {
  const glm::dvec3 sum = v_ + l;
  const double length = glm::length(sum);
  if (!(length > 0.0)) return {};
  glm::dvec3 h = sum / length;
  const double v_dot_h = 0.5 * length;  // v.h = (1 + v.l) / |v + l| = |v + l| / 2
  LobeSample out;
  if (kind_ == LtcTargetKind::Ggx) {
    // Visible normals reflected: pdf = D_v(h) / (4 v.h) = G1(v) D(h) / (4 v.z); zero where h is
    // below the horizon.
    const double d = ggx_ndf(h, alpha_);
    out.pdf = g1_v_ * d / (4.0 * v_.z);
    if (l.z > 0.0) out.value = d / (4.0 * v_.z * (1.0 + lambda_v_ + ggx_lambda(l, alpha_)));
  } else {
    // D sampled over the whole hemisphere of normals: h and -h reflect v to the same l, so the
    // sampled normal is whichever of them points up (v.h < 0 for it when l is below the horizon).
    if (h.z < 0.0) h = -h;
    const double d = ggx_ndf(h, alpha_);
    out.pdf = d / (4.0 * v_dot_h * total_ndf_);
    if (l.z > 0.0) out.value = d / (4.0 * v_dot_h);
  }
  return out;
}

glm::dvec3 LtcTarget::sample_half_vector(glm::dvec2 u) const {
  return kind_ == LtcTargetKind::Ggx ? sample_ggx_visible_normal(v_, u, alpha_) : sample_ggx_ndf(u, alpha_);
}

glm::dvec3 LtcTarget::reflect_view(const glm::dvec3& h) const { return 2.0 * glm::dot(v_, h) * h - v_; }

}  // namespace glintlab
