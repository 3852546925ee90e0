#include "core/student_t.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glintlab {

namespace {

/// The density of Student's t at x.
double density(double x, double nu) {
  const double log_norm = std::lgamma(0.5 * (nu + 1.0)) - std::lgamma(0.5 * nu) - 0.5 * std::log(nu * std::numbers::pi);
  return std::exp(log_norm - 0.5 * (nu + 1.0) * std::log1p(x * x / nu));
}

}  // namespace

double student_t_cdf(double t, int dof) {
  if (dof < 1) throw std::invalid_argument("student_t_cdf: dof must be at least 1");
  if (t < 0.0) return 1.0 - student_t_cdf(-t, dof);
  // 1/2 + the integral of the density over [0, t], substituted x = tan(u) (the density's heavy
  // tails become a smooth, bounded integrand on [0, atan t]) and summed by composite Simpson.
  const double nu = dof, end = std::atan(t);
  constexpr int kIntervals = 2048;  // even; error far below 1e-10 for dof >= 1
  const double h = end / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double u = i * h, x = std::tan(u), c = std::cos(u);
    const double f = density(x, nu) / (c * c);
    sum += f * (i == 0 || i == kIntervals ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return 0.5 + sum * h / 3.0;
}

double student_t_quantile(double p, int dof) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("student_t_quantile: p must be in (0, 1)");
  if (p < 0.5) return -student_t_quantile(1.0 - p, dof);
  // Bisection on the CDF in u = atan(t), where the quantile lies in [0, pi/2).
  double lo = 0.0, hi = 0.5 * std::numbers::pi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(std::tan(mid), dof) < p ? lo : hi) = mid;
  }
  return std::tan(0.5 * (lo + hi));
}

}  // namespace glintlab
