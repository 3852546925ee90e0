#pragma once
// Pearson's chi-square goodness-of-fit test of samplers, as pbrt-v4 and Mitsuba 3 run it: a
// histogram of many samples against the counts the sampler's density expects per bin.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <ostream>
#include <vector>

namespace glintlab::test {

/// Regularised upper incomplete gamma Q(a, x): series below a + 1, continued fraction above
/// (Abramowitz & Stegun 6.5.29 and 6.5.31).
inline double gamma_q(double a, double x) {
  if (x <= 0) return 1;
  const double log_prefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < 10000 && std::abs(term) > 1e-16 * std::abs(sum); ++n) sum += term *= x / (a + n);
    return 1 - sum * std::exp(log_prefix);
  }
  // Lentz's method for 1 / (x + 1 - a - 1 (1 - a) / (x + 3 - a - ...)).
  double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
  for (int n = 1; n < 10000; ++n) {
    const double an = -n * (n - a);
    b += 2;
    d = an * d + b;
    d = std::abs(d) < 1e-300 ? 1e-300 : d;
    c = b + an / c;
    c = std::abs(c) < 1e-300 ? 1e-300 : c;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1) < 1e-15) break;
  }
  return std::exp(log_prefix) * h;
}

struct ChiSquare {
  double chi2 = 0;
  int dof = 0;
  double p = 1;
  /// At significance 1 - (1 - 0.01)^(1 / tests): a 1% chance that any of a file's `tests` fails.
  [[nodiscard]] bool passes(int tests = 1) const { return p > 1 - std::pow(1 - 0.01, 1.0 / tests); }
};

/// Pearson's chi-square of observed against expected counts; bins expecting fewer than 5 samples
/// are pooled (sorted by expectation, merged until the pool expects 5), as pbrt-v4 and Mitsuba do.
/// (Where a density has no support at all, tests count the samples there separately.)
inline ChiSquare chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquare r;
  std::vector<std::size_t> order(observed.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto x, auto y) { return expected[x] < expected[y]; });
  double pool_obs = 0, pool_exp = 0;
  int cells = 0;
  for (const auto i : order) {
    if (expected[i] < 5 || (pool_exp > 0 && pool_exp < 5)) {
      pool_obs += observed[i];
      pool_exp += expected[i];
      if (pool_exp < 5) continue;
      r.chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
      pool_obs = pool_exp = 0;
      ++cells;
      continue;
    }
    r.chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++cells;
  }
  if (pool_exp > 0) {  // a remainder expecting fewer than 5: still counted, as one cell
    r.chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
    ++cells;
  }
  r.dof = cells - 1;
  r.p = gamma_q(0.5 * r.dof, 0.5 * r.chi2);
  return r;
}

inline std::ostream& operator<<(std::ostream& o, const ChiSquare& c) {
  return o << "chi2 " << c.chi2 << " dof " << c.dof << " p " << c.p;
}

}  // namespace glintlab::test
