#include "render/reference_estimate.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>

#include "core/error.hpp"
#include "core/student_t.hpp"

namespace glintlab {

namespace {

glm::dvec3 as_double(const glm::vec3& v) { return glm::dvec3(v); }

double luminance_of(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/// Unbiased variance of the mean of n samples from their sum and sum of squares.
glm::dvec3 variance_of_mean(const glm::dvec3& sum, const glm::dvec3& squares, int n) {
  if (n < 2) return glm::dvec3(0.0);
  const glm::dvec3 mean = sum / double(n);
  const glm::dvec3 var = (squares - double(n) * mean * mean) / double(n - 1);
  return glm::max(var, glm::dvec3(0.0)) / double(n);
}

}  // namespace

double ReferenceFrame::noise_rmse() const {
  if (passes < 2) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (const auto& e : standard_error.pixels()) sum += glm::dot(glm::dvec3(e), glm::dvec3(e));
  return std::sqrt(sum / (3.0 * static_cast<double>(standard_error.pixel_count())));
}

double ReferenceFrame::interval_scale() const {
  if (passes < 2) return std::numeric_limits<double>::quiet_NaN();
  // Computed once per pass count (a numerical quantile: about a millisecond).
  static std::mutex mutex;
  static std::map<int, double> scales;
  const std::lock_guard lock(mutex);
  auto [it, added] = scales.try_emplace(passes, 0.0);
  if (added) it->second = student_t_quantile(0.975, passes - 1) / student_t_quantile(0.975, 1000000);
  return it->second;
}

Image ReferenceFrame::stated_error() const {
  const int w = standard_error.width(), h = standard_error.height();
  Image out(w, h);
  const double scale = interval_scale();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 squares(0.0);
      int n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h) continue;
          const glm::dvec3 e(standard_error.at(x + dx, y + dy));
          squares += e * e;
          ++n;
        }
      const glm::dvec3 own(standard_error.at(x, y));
      out.at(x, y) = glm::vec3(scale * glm::max(own, glm::sqrt(squares / double(n))));
    }
  return out;
}

double ReferenceFrame::relative_energy_error(bool specular) const {
  const auto& values = specular ? pass_luminance_specular : pass_luminance;
  const auto n = static_cast<double>(values.size());
  if (values.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0, squares = 0.0;
  for (double v : values) sum += v, squares += v * v;
  const double mean = sum / n;
  const double var = std::max(squares - n * mean * mean, 0.0) / (n - 1.0);
  return mean > 0.0 ? interval_scale() * std::sqrt(var / n) / mean : 0.0;
}

ReferenceAccumulator::ReferenceAccumulator(int width, int height, int spp_per_pass)
    : width_(width), height_(height), spp_per_pass_(spp_per_pass) {
  const auto n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  sum_.assign(n, glm::dvec3(0.0));
  sum_squares_ = specular_sum_ = even_sum_ = sum_;
}

ReferenceAccumulator::ReferenceAccumulator(const ReferenceFrame& earlier, int spp_per_pass)
    : ReferenceAccumulator(earlier.mean.total.width(), earlier.mean.total.height(), spp_per_pass) {
  passes_ = earlier.passes;
  pass_luminance_ = earlier.pass_luminance;
  pass_luminance_specular_ = earlier.pass_luminance_specular;
  if (static_cast<int>(pass_luminance_.size()) != passes_ || pass_luminance_specular_.size() != pass_luminance_.size())
    throw RuntimeFailure("reference frame with " + std::to_string(passes_) + " passes but " +
                         std::to_string(pass_luminance_.size()) + " pass means");
  const double n = passes_;
  const int even = (passes_ + 1) / 2;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    const glm::dvec3 mean = as_double(earlier.mean.total.pixels()[i]);
    const glm::dvec3 se = as_double(earlier.standard_error.pixels()[i]);
    sum_[i] = mean * n;
    // Inverts variance_of_mean: squares = (n - 1) n se^2 + n mean^2.
    sum_squares_[i] = (n - 1.0) * n * se * se + n * mean * mean;
    specular_sum_[i] = as_double(earlier.mean.specular.pixels()[i]) * n;
    even_sum_[i] = as_double(earlier.even_passes.pixels()[i]) * double(even);
  }
}

void ReferenceAccumulator::add_pass(const Frame& pass) {
  if (pass.total.width() != width_ || pass.total.height() != height_)
    throw RuntimeFailure("reference pass of a different size");
  const bool even = passes_ % 2 == 0;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    const glm::dvec3 v = as_double(pass.total.pixels()[i]);
    sum_[i] += v;
    sum_squares_[i] += v * v;
    specular_sum_[i] += as_double(pass.specular.pixels()[i]);
    if (even) even_sum_[i] += v;
  }
  pass_luminance_.push_back(luminance_of(pass.total.mean()));
  pass_luminance_specular_.push_back(luminance_of(pass.specular.mean()));
  ++passes_;
}

ReferenceFrame ReferenceAccumulator::result() const {
  ReferenceFrame r;
  r.passes = passes_;
  r.spp = passes_ * spp_per_pass_;
  r.pass_luminance = pass_luminance_;
  r.pass_luminance_specular = pass_luminance_specular_;
  r.mean = {Image(width_, height_), Image(width_, height_)};
  r.standard_error = r.even_passes = r.odd_passes = Image(width_, height_);
  const int even = (passes_ + 1) / 2, odd = passes_ / 2;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    const double n = std::max(passes_, 1);
    r.mean.total.pixels()[i] = glm::vec3(sum_[i] / n);
    r.mean.specular.pixels()[i] = glm::vec3(specular_sum_[i] / n);
    r.standard_error.pixels()[i] = glm::vec3(glm::sqrt(variance_of_mean(sum_[i], sum_squares_[i], passes_)));
    const glm::dvec3 even_mean = even > 0 ? even_sum_[i] / double(even) : glm::dvec3(0.0);
    r.even_passes.pixels()[i] = glm::vec3(even_mean);
    r.odd_passes.pixels()[i] = glm::vec3(odd > 0 ? (sum_[i] - even_sum_[i]) / double(odd) : even_mean);
  }
  return r;
}

}  // namespace glintlab
