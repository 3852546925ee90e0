#pragma once
// Deterministic quadrature over the sphere for the LTC tests: the truth the sampled estimates
// and the fitter are checked against (it shares no code with them).
#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

namespace glintlab::test {

/// The integral of g over directions with polar angle in [theta0, theta1] about +z, by the
/// midpoint rule in (cos theta, phi) on an n x 2n grid (dw = d cos d phi).
template <class G>
double integrate_band(G&& g, double theta0, double theta1, int n) {
  const double c0 = std::cos(theta1), c1 = std::cos(theta0);
  double sum = 0.0;
  for (int a = 0; a < n; ++a) {
    const double c = c0 + (c1 - c0) * (a + 0.5) / n, s = std::sqrt(std::max(0.0, 1.0 - c * c));
    for (int b = 0; b < 2 * n; ++b) {
      const double phi = std::numbers::pi * (b + 0.5) / n;
      sum += g(glm::dvec3(s * std::cos(phi), s * std::sin(phi), c));
    }
  }
  return sum * (c1 - c0) / n * std::numbers::pi / n;
}

template <class G>
double integrate_sphere(G&& g, int n) { return integrate_band(g, 0.0, std::numbers::pi, n); }
template <class G>
double integrate_hemisphere(G&& g, int n) { return integrate_band(g, 0.0, 0.5 * std::numbers::pi, n); }

}  // namespace glintlab::test
