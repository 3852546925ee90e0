#include "core/image.hpp"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

namespace glintlab {

Image::Image(int width, int height, glm::vec3 fill)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

std::size_t Image::count_non_finite() const {
  return static_cast<std::size_t>(std::count_if(pixels_.begin(), pixels_.end(), [](const glm::vec3& p) {
    return !std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b);
  }));
}

Image Image::crop(int x0, int y0, int w, int h) const {
  x0 = std::clamp(x0, 0, width_);
  y0 = std::clamp(y0, 0, height_);
  w = std::clamp(w, 0, width_ - x0);
  h = std::clamp(h, 0, height_ - y0);
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.at(x, y) = at(x0 + x, y0 + y);
  return out;
}

Image Image::upscale(int factor) const {
  Image out(width_ * factor, height_ * factor);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) out.at(x, y) = at(x / factor, y / factor);
  return out;
}

glm::dvec3 Image::mean() const {
  glm::dvec3 sum(0.0);
  for (const auto& p : pixels_) sum += glm::dvec3(p);
  return pixels_.empty() ? sum : sum / static_cast<double>(pixels_.size());
}

}  // namespace glintlab
