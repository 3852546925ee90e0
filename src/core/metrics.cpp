#include "core/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/colour.hpp"

namespace glintlab {

namespace {
void require_same_size(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height())
    throw std::invalid_argument("metrics: image sizes differ (" + std::to_string(a.width()) + "x" +
                                std::to_string(a.height()) + " vs " + std::to_string(b.width()) + "x" +
                                std::to_string(b.height()) + ")");
}
}  // namespace

double rmse(const Image& test, const Image& ref) {
  require_same_size(test, ref);
  if (test.empty()) return 0.0;
  double sum = 0;
  for (std::size_t i = 0; i < test.pixel_count(); ++i) {
    const glm::dvec3 d = glm::dvec3(test.pixels()[i]) - glm::dvec3(ref.pixels()[i]);
    sum += d.x * d.x + d.y * d.y + d.z * d.z;
  }
  return std::sqrt(sum / (3.0 * static_cast<double>(test.pixel_count())));
}

double psnr(double rmse_value) {
  if (rmse_value <= 0) return std::numeric_limits<double>::infinity();
  return -20.0 * std::log10(rmse_value);
}

double max_abs_error(const Image& test, const Image& ref) {
  require_same_size(test, ref);
  double m = 0;
  for (std::size_t i = 0; i < test.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      m = std::max(m, std::abs(static_cast<double>(test.pixels()[i][c]) - ref.pixels()[i][c]));
  return m;
}

double energy_ratio(const Image& test, const Image& ref) {
  require_same_size(test, ref);
  double a = 0, b = 0;
  for (std::size_t i = 0; i < test.pixel_count(); ++i) {
    a += luminance(test.pixels()[i]);
    b += luminance(ref.pixels()[i]);
  }
  if (b == 0) return a == 0 ? 1.0 : std::numeric_limits<double>::infinity();
  return a / b;
}

Image abs_error_map(const Image& test, const Image& ref) {
  require_same_size(test, ref);
  Image out(test.width(), test.height());
  for (std::size_t i = 0; i < test.pixel_count(); ++i)
    out.pixels()[i] = glm::vec3(std::abs(luminance(test.pixels()[i]) - luminance(ref.pixels()[i])));
  return out;
}

float error_percentile(const Image& error_map, double fraction) {
  if (error_map.empty()) return 0.0f;
  std::vector<float> values;
  values.reserve(error_map.pixel_count());
  for (const glm::vec3& p : error_map.pixels()) values.push_back(p.r);
  const auto nth = values.begin() + static_cast<std::ptrdiff_t>(std::clamp(fraction, 0.0, 1.0) *
                                                                  static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), nth, values.end());
  return *nth;
}

namespace {
// Calls f(tile_x, tile_y, pixel_index) for every pixel of every full block x block tile.
void require_block(int block) {
  if (block < 1) throw std::invalid_argument("metrics: block size " + std::to_string(block) + " (must be >= 1)");
}

template <typename F>
void for_each_tile_pixel(const Image& image, int block, F f) {
  for (int ty = 0; ty + block <= image.height(); ty += block)
    for (int tx = 0; tx + block <= image.width(); tx += block)
      for (int y = ty; y < ty + block; ++y)
        for (int x = tx; x < tx + block; ++x)
          f(tx / block, ty / block, static_cast<std::size_t>(y) * image.width() + x);
}

// Each full tile's mean (RGB), row by row.
std::vector<glm::dvec3> tile_means(const Image& image, int block) {
  const int columns = image.width() / block;
  std::vector<glm::dvec3> means(static_cast<std::size_t>(columns) * (image.height() / block), glm::dvec3(0.0));
  for_each_tile_pixel(image, block, [&](int tx, int ty, std::size_t i) {
    means[static_cast<std::size_t>(ty) * columns + tx] += glm::dvec3(image.pixels()[i]);
  });
  for (glm::dvec3& m : means) m /= double(block) * block;
  return means;
}

// The mean square of luminance minus its 3 x 3 mean, over the pixels with a full neighbourhood:
// detail at the pixel's scale, with every linear gradient taken out exactly (the box is symmetric).
// Of white noise of variance v it keeps (1 - 1/9)^2 v + 8 v / 81 = 8 v / 9.
constexpr double kHighPassNoiseShare = 8.0 / 9.0;
double high_pass_power(const Image& image) {
  double sum = 0, count = 0;
  for (int y = 1; y + 1 < image.height(); ++y)
    for (int x = 1; x + 1 < image.width(); ++x) {
      double box = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) box += luminance(image.at(x + dx, y + dy));
      const double d = luminance(image.at(x, y)) - box / 9.0;
      sum += d * d;
      count += 1;
    }
  return count > 0 ? sum / count : 0.0;
}
}  // namespace

double block_rmse(const Image& test, const Image& ref, int block) {
  require_same_size(test, ref);
  require_block(block);
  const std::vector<glm::dvec3> a = tile_means(test, block), b = tile_means(ref, block);
  if (a.empty()) return 0.0;
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 d = a[i] - b[i];
    sum += glm::dot(d, d);
  }
  return std::sqrt(sum / (3.0 * static_cast<double>(a.size())));
}

double glint_detail(const Image& image, const Image* standard_error) {
  double power = high_pass_power(image);
  if (standard_error && !standard_error->empty()) {
    require_same_size(*standard_error, image);
    double noise = 0, count = 0;
    for (int y = 1; y + 1 < image.height(); ++y)
      for (int x = 1; x + 1 < image.width(); ++x) {
        const double e = luminance(standard_error->at(x, y));
        noise += e * e;
        count += 1;
      }
    if (count > 0) power -= kHighPassNoiseShare * noise / count;
  }
  return std::sqrt(std::max(power, 0.0));
}

double sparkle_distance(const Image& test, const Image& ref, int block) {
  require_same_size(test, ref);
  require_block(block);
  const int columns = test.width() / block, rows = test.height() / block;
  if (columns == 0 || rows == 0) return 0.0;
  std::vector<float> a, b;
  double distance = 0, reference_sum = 0;
  for (int ty = 0; ty < rows; ++ty)
    for (int tx = 0; tx < columns; ++tx) {
      a.clear();
      b.clear();
      for (int y = ty * block; y < (ty + 1) * block; ++y)
        for (int x = tx * block; x < (tx + 1) * block; ++x) {
          a.push_back(luminance(test.at(x, y)));
          b.push_back(luminance(ref.at(x, y)));
        }
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      // W1 of two empirical distributions of equal size: the mean gap between their order statistics.
      for (std::size_t i = 0; i < a.size(); ++i) {
        distance += std::abs(double(a[i]) - b[i]);
        reference_sum += b[i];
      }
    }
  if (reference_sum <= 0) return distance > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return distance / reference_sum;
}

Image displayed_linear(const Image& radiance, float exposure) {
  const float gain = std::exp2(exposure);
  Image out(radiance.width(), radiance.height());
  for (std::size_t i = 0; i < radiance.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) out.pixels()[i][c] = aces_filmic(gain * radiance.pixels()[i][c]);
  return out;
}

MetricsReference::MetricsReference(const Image& total, const Image& specular, const MetricsViewing& viewing)
    : total_(total),
      specular_(specular),
      viewing_(viewing),
      displayed_(displayed_linear(total, viewing.display_exposure), viewing.pixels_per_degree),
      hdr_(total, viewing.pixels_per_degree, flip::automatic_exposures(total)) {}

std::vector<float> MetricsReference::flip_ldr_map(const Image& total) const {
  require_same_size(total, total_);
  return flip::error_map(flip::Perception(displayed_linear(total, viewing_.display_exposure), viewing_.pixels_per_degree),
                         displayed_);
}

std::vector<float> MetricsReference::flip_hdr_map(const Image& total) const {
  require_same_size(total, total_);
  return hdr_.error_map(total);
}

ImageMetrics MetricsReference::measure(const Image& total, const Image& specular,
                                       std::vector<float>* flip_ldr_map_out) const {
  ImageMetrics m;
  m.rmse = rmse(total, total_);
  m.rmse_specular = rmse(specular, specular_);
  m.psnr = psnr(m.rmse);
  m.energy_ratio = energy_ratio(total, total_);
  m.energy_ratio_specular = energy_ratio(specular, specular_);
  m.max_error = max_abs_error(total, total_);
  m.block_rmse = block_rmse(total, total_, kStatisticsBlock);
  m.glint_detail = glint_detail(total);
  std::vector<float> ldr_map = flip_ldr_map(total);
  m.flip_ldr = flip::mean(ldr_map);
  if (flip_ldr_map_out) *flip_ldr_map_out = std::move(ldr_map);
  m.flip_hdr = flip::mean(flip_hdr_map(total));
  m.sparkle_distance = sparkle_distance(total, total_, kSparkleBlock);
  return m;
}

void FlickerAccumulator::add_frame(const Image& method, const Image& reference) {
  require_same_size(method, reference);
  Image error(method.width(), method.height());
  for (std::size_t i = 0; i < error.pixel_count(); ++i)
    error.pixels()[i] = method.pixels()[i] - reference.pixels()[i];
  if (frames_ > 0) {
    require_same_size(error, previous_error_);
    double frame_sum = 0;
    for (std::size_t i = 0; i < error.pixel_count(); ++i)
      for (int c = 0; c < 3; ++c)
        frame_sum += std::abs(static_cast<double>(error.pixels()[i][c]) - previous_error_.pixels()[i][c]);
    const double frame_count = 3.0 * static_cast<double>(error.pixel_count());
    per_frame_.push_back(frame_count > 0 ? frame_sum / frame_count : 0.0);
    sum_ += frame_sum;
    count_ += frame_count;
  }
  previous_error_ = std::move(error);
  ++frames_;
}

double FlickerAccumulator::flicker() const { return count_ > 0 ? sum_ / count_ : 0.0; }

}  // namespace glintlab
