#pragma once
// An NDF image: the P-NDF of one footprint over the projected half vector s = h.xy, as an
// N x N image of the square [-extent, extent]^2. A pixel holds the AVERAGE of P over its area, so
// the image's sum times pixel_area() is the NDF's mass inside the square (1 when none falls outside).
#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

namespace glintlab {

struct NdfGrid {
  int resolution = 64;  ///< N pixels per side
  double extent = 1.0;  ///< the square is [-extent, extent]^2 of s

  [[nodiscard]] double pixel_size() const { return 2.0 * extent / resolution; }
  [[nodiscard]] double pixel_area() const { return pixel_size() * pixel_size(); }
  /// Continuous pixel coordinates of s: pixel i covers [i, i + 1).
  [[nodiscard]] glm::dvec2 to_pixels(glm::dvec2 s) const { return (s + extent) / pixel_size(); }
  [[nodiscard]] glm::dvec2 pixel_centre(int i, int j) const {
    return glm::dvec2(i + 0.5, j + 0.5) * pixel_size() - extent;
  }
  [[nodiscard]] std::size_t pixel_count() const {
    return static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution);
  }
};

struct NdfImage {
  NdfGrid grid;
  std::vector<float> values;  ///< row j (the t = s.y axis) major, pixel i (s.x) minor

  [[nodiscard]] float at(int i, int j) const {
    return values[static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.resolution) + static_cast<std::size_t>(i)];
  }
  /// Sum of values times the pixel area: the NDF's mass inside the square.
  [[nodiscard]] double mass() const;
};

/// sqrt(sum (a - b)^2 / sum b^2): the relative L2 distance of two images on the same grid.
double relative_l2(const NdfImage& a, const NdfImage& b);

}  // namespace glintlab
