#include "tables/ltc/ltc_sphere.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace glintlab {
namespace {

/// The integral over azimuth of max(0, a + b cos(phi)), b >= 0: the cosine of the points of one
/// ring of the cap, at polar angle rho from its centre (a = z cos rho, b = sqrt(1 - z^2) sin rho).
double ring_integral(double a, double b) {
  if (a >= b) return 2.0 * std::numbers::pi * a;
  if (a <= -b) return 0.0;
  const double phi0 = std::acos(-a / b);  // where the ring meets the horizon
  return 2.0 * (a * phi0 + b * std::sin(phi0));
}

/// Gauss-Legendre nodes and weights of order 32 on [-1, 1], by Newton on P_n.
struct GaussLegendre {
  static constexpr int kOrder = 32;
  std::array<double, kOrder> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < kOrder; ++i) {
      double t = std::cos(std::numbers::pi * (i + 0.75) / (kOrder + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = t;  // P_0, P_1, then the recurrence up to P_n
        for (int k = 2; k <= kOrder; ++k) {
          const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = kOrder * (t * p1 - p0) / (t * t - 1.0);
        const double step = p1 / derivative;
        t -= step;
        if (std::abs(step) < 1e-15) break;
      }
      x[i] = t;
      w[i] = 2.0 / ((1.0 - t * t) * derivative * derivative);
    }
  }
};

/// int_{r0}^{r1} ring_integral(rho) sin(rho) d rho.
double rings(double z, double r0, double r1) {
  static const GaussLegendre gl;
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  double sum = 0.0;
  for (int i = 0; i < GaussLegendre::kOrder; ++i) {
    const double rho = 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * gl.x[i];
    sum += gl.w[i] * ring_integral(z * std::cos(rho), s * std::sin(rho)) * std::sin(rho);
  }
  return 0.5 * (r1 - r0) * sum;
}

}  // namespace

double clipped_cap_form_factor(double z, double sin2_sigma) {
  z = std::clamp(z, -1.0, 1.0);
  const double sigma = std::asin(std::sqrt(std::clamp(sin2_sigma, 0.0, 1.0)));
  const double omega = std::acos(z);  // the centre's polar angle
  // Rings with rho < |pi/2 - omega| lie wholly above (or below) the horizon; beyond, they cross it
  // and the integrand has a kink there: integrate the two parts separately, and the crossing part
  // in pieces, since the kink of acos at the ring that just touches is steep.
  const double whole = std::min(sigma, std::abs(0.5 * std::numbers::pi - omega));
  double sum = rings(z, 0.0, whole);
  constexpr int kPieces = 8;
  for (int i = 0; i < kPieces; ++i)
    sum += rings(z, whole + (sigma - whole) * i / kPieces, whole + (sigma - whole) * (i + 1) / kPieces);
  return sum / std::numbers::pi;
}

double clipped_cap_ratio(double z, double form_factor_length) {
  if (!(form_factor_length > 0.0)) return std::max(z, 0.0);
  return clipped_cap_form_factor(z, form_factor_length) / form_factor_length;
}

}  // namespace glintlab
