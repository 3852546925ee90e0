#include "scene/lights/environment_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "scene/lights/environment_map.hpp"

namespace glintlab {
namespace {

/// Writes the normalised running sum of `values` into `out` (values.size() + 1 entries: 0, ..., 1),
/// or the uniform CDF if they sum to 0; returns the sum.
double write_cdf(std::span<const double> values, float* out) {
  const std::size_t n = values.size();
  double sum = 0;
  for (double v : values) sum += v;
  double running = 0;
  out[0] = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    running += values[i];
    out[i + 1] = static_cast<float>(sum > 0 ? running / sum : double(i + 1) / double(n));
  }
  out[n] = 1.0f;  // exact, whatever the rounding of the running sum
  return sum;
}

/// The interval i of a CDF of n intervals with cdf[i] <= u < cdf[i + 1] (so never one of zero
/// width), and where u lies within it.
struct Interval {
  int index;
  double offset;  ///< in [0, 1)
  double probability;
};

Interval find_interval(const float* cdf, int n, double u) {
  const float* hit = std::upper_bound(cdf, cdf + n + 1, static_cast<float>(u));
  const int i = std::clamp(static_cast<int>(hit - cdf) - 1, 0, n - 1);
  const double lo = cdf[i], hi = cdf[i + 1];
  const double width = hi - lo;
  return {i, width > 0 ? std::clamp((u - lo) / width, 0.0, 1.0) : 0.5, width};
}

}  // namespace

EnvironmentSampling build_environment_sampling(const Image& radiance) {
  EnvironmentSampling s;
  s.width = radiance.width();
  s.height = radiance.height();
  const int w = s.width, h = s.height;
  s.cdf.assign(static_cast<std::size_t>(w + 1) * (h + 1), 0.0f);
  std::vector<double> row(static_cast<std::size_t>(w));
  std::vector<double> row_sums(static_cast<std::size_t>(h));
  double total = 0;
  for (int y = 0; y < h; ++y) {
    // sin(theta) at the row's centre: the Jacobian of (u, v) -> directions, per row.
    const double sin_theta = std::sin(std::numbers::pi * (y + 0.5) / h);
    for (int x = 0; x < w; ++x)
      row[static_cast<std::size_t>(x)] = std::max(0.0, double(luminance(radiance.at(x, y)))) * sin_theta;
    row_sums[static_cast<std::size_t>(y)] = write_cdf(row, s.cdf.data() + static_cast<std::size_t>(y) * (w + 1));
    total += row_sums[static_cast<std::size_t>(y)];
  }
  write_cdf(row_sums, s.cdf.data() + static_cast<std::size_t>(h) * (w + 1));
  s.integral = total / (double(w) * h);
  return s;
}

glm::dvec2 sample_environment_uv(const EnvironmentSampling& s, glm::dvec2 u, double* pdf_uv) {
  const float* marginal = s.cdf.data() + static_cast<std::size_t>(s.height) * s.stride();
  const Interval row = find_interval(marginal, s.height, u.y);
  const float* conditional = s.cdf.data() + static_cast<std::size_t>(row.index) * s.stride();
  const Interval column = find_interval(conditional, s.width, u.x);
  // The density in uv of a texel chosen with probability p_row p_column: p_row H p_column W (= f / I).
  if (pdf_uv) *pdf_uv = s.integral > 0 ? row.probability * s.height * column.probability * s.width : 0.0;
  return {(column.index + column.offset) / s.width, (row.index + row.offset) / s.height};
}

double environment_pdf_uv(const EnvironmentSampling& s, glm::dvec2 uv) {
  if (!(s.integral > 0)) return 0.0;
  const int x = std::clamp(static_cast<int>(uv.x * s.width), 0, s.width - 1);
  const int y = std::clamp(static_cast<int>(uv.y * s.height), 0, s.height - 1);
  const double p_row = double(s.marginal(y + 1)) - s.marginal(y);
  const double p_column = double(s.conditional(y, x + 1)) - s.conditional(y, x);
  return p_row * s.height * p_column * s.width;
}

double environment_pdf(const EnvironmentSampling& s, glm::dvec3 d) {
  const glm::dvec2 uv = environment_uv(d);
  const double sin_theta = std::sin(std::numbers::pi * uv.y);
  return sin_theta > 0 ? environment_pdf_uv(s, uv) / (2 * std::numbers::pi * std::numbers::pi * sin_theta) : 0.0;
}

}  // namespace glintlab
