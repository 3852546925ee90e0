#pragma once
// A linear, floating-point RGB image, row 0 at the top.
#include "core/math.hpp"
#include <vector>

namespace glintlab {

class Image {
 public:
  Image() = default;
  Image(int width, int height, glm::vec3 fill = glm::vec3(0.0f));

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] std::size_t pixel_count() const { return pixels_.size(); }
  [[nodiscard]] bool empty() const { return pixels_.empty(); }

  glm::vec3& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  [[nodiscard]] const glm::vec3& at(int x, int y) const {
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  std::vector<glm::vec3>& pixels() { return pixels_; }
  [[nodiscard]] const std::vector<glm::vec3>& pixels() const { return pixels_; }

  /// Pixels with a NaN or infinite channel.
  [[nodiscard]] std::size_t count_non_finite() const;
  /// Sub-image [x0, x0+w) x [y0, y0+h), clipped to the image.
  [[nodiscard]] Image crop(int x0, int y0, int w, int h) const;
  /// Nearest-neighbour enlargement by an integer factor (for crops people look at).
  [[nodiscard]] Image upscale(int factor) const;
  /// Mean of each channel.
  [[nodiscard]] glm::dvec3 mean() const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<glm::vec3> pixels_;
};

/// Rec. 709 luminance.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace glintlab
