#include "view/display_compose.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <stdexcept>

#include "core/colour.hpp"
#include "core/metrics.hpp"

namespace glintlab {

namespace {

void require_same_size(const Image& a, const Image& b, const char* what) {
  if (a.width() != b.width() || a.height() != b.height()) throw std::invalid_argument(std::string(what) + ": sizes differ");
}

}  // namespace

Image split_images(const Image& left, const Image& right, float split) {
  require_same_size(left, right, "split_images");
  const int edge = static_cast<int>(std::lround(std::clamp(split, 0.0f, 1.0f) * static_cast<float>(left.width())));
  Image out = right;
  for (int y = 0; y < left.height(); ++y)
    for (int x = 0; x < edge; ++x) out.at(x, y) = left.at(x, y);
  return out;
}

Image blend_images(const Image& base, const Image& overlay, float opacity) {
  require_same_size(base, overlay, "blend_images");
  const float t = std::clamp(opacity, 0.0f, 1.0f);
  Image out(base.width(), base.height());
  for (std::size_t i = 0; i < base.pixel_count(); ++i)
    out.pixels()[i] = glm::mix(base.pixels()[i], overlay.pixels()[i], t);
  return out;
}

Image error_map_display(const Image& method, const Image& reference) {
  const Image error = abs_error_map(method, reference);
  const float scale = error_percentile(error, kErrorMapPercentile);
  return false_colour(error, scale > 0.0f ? scale : 1.0f);
}

std::vector<std::uint8_t> to_rgba8(const Image& display) {
  std::vector<std::uint8_t> out(display.pixel_count() * 4, 255);
  for (std::size_t i = 0; i < display.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      out[i * 4 + c] = unorm8(display.pixels()[i][c]);
  return out;
}

}  // namespace glintlab
