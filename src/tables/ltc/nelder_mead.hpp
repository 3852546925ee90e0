#pragma once
// The downhill simplex method of Nelder and Mead (1965), with the usual coefficients (reflection
// 1, expansion 2, contraction 1/2, shrink 1/2): what Heitz et al. 2016 (sec. 4.3) minimise the
// fitting error with. Derivative-free, so the Monte-Carlo error of a few thousand samples is fine.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace glintlab {

/// Minimises f over R^N from `start` with an initial simplex of `step` along each axis. Stops
/// after `max_evaluations` calls of f or when the simplex's values differ by less than
/// `tolerance` relative to the best. Returns the best point; `best_value` receives f there.
template <std::size_t N, class F>
std::array<double, N> nelder_mead(F&& f, std::array<double, N> start, double step, int max_evaluations,
                                  double tolerance, double* best_value = nullptr) {
  using Point = std::array<double, N>;
  std::array<Point, N + 1> x;
  std::array<double, N + 1> fx;
  int evaluations = 0;
  auto eval = [&](const Point& p) {
    ++evaluations;
    return f(p);
  };
  for (std::size_t i = 0; i <= N; ++i) {
    x[i] = start;
    if (i > 0) x[i][i - 1] += step;
    fx[i] = eval(x[i]);
  }
  auto along = [](const Point& from, const Point& to, double t) {  // from + t (to - from)
    Point p;
    for (std::size_t k = 0; k < N; ++k) p[k] = from[k] + t * (to[k] - from[k]);
    return p;
  };
  while (evaluations < max_evaluations) {
    std::array<std::size_t, N + 1> order;
    for (std::size_t i = 0; i <= N; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fx[a] < fx[b]; });
    const std::size_t best = order[0], worst = order[N], second = order[N - 1];
    if (fx[worst] - fx[best] <= tolerance * std::abs(fx[best]) + 1e-300) break;
    Point centroid{};
    for (std::size_t i = 0; i <= N; ++i)
      if (i != worst)
        for (std::size_t k = 0; k < N; ++k) centroid[k] += x[i][k] / static_cast<double>(N);

    const Point reflected = along(centroid, x[worst], -1.0);
    const double f_reflected = eval(reflected);
    if (f_reflected < fx[best]) {
      const Point expanded = along(centroid, x[worst], -2.0);
      const double f_expanded = eval(expanded);
      if (f_expanded < f_reflected) x[worst] = expanded, fx[worst] = f_expanded;
      else x[worst] = reflected, fx[worst] = f_reflected;
      continue;
    }
    if (f_reflected < fx[second]) {
      x[worst] = reflected, fx[worst] = f_reflected;
      continue;
    }
    // Contract towards the better of the worst point and its reflection.
    const bool outside = f_reflected < fx[worst];
    const Point contracted = along(centroid, outside ? reflected : x[worst], 0.5);
    const double f_contracted = eval(contracted);
    if (f_contracted < std::min(f_reflected, fx[worst])) {
      x[worst] = contracted, fx[worst] = f_contracted;
      continue;
    }
    for (std::size_t i = 0; i <= N; ++i)  // shrink towards the best
      if (i != best) {
        x[i] = along(x[best], x[i], 0.5);
        fx[i] = eval(x[i]);
      }
  }
  const std::size_t best = static_cast<std::size_t>(std::min_element(fx.begin(), fx.end()) - fx.begin());
  if (best_value) *best_value = fx[best];
  return x[best];
}

}  // namespace glintlab
