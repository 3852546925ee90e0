#pragma once
// The chi-square test of an NDF sampler (tests/chi_square.hpp) on an NDF image's grid: samples of s
// binned on (N + 1)^2 bins centred on the grid's pixel corners, -extent + i h (the bilinear
// density's nodes), and the counts a density expects there (its value at the bin's centre times
// the bin's area and the sample count).
#include <cmath>
#include <functional>
#include <glm/vec2.hpp>
#include <vector>

#include "prefilter/ndf_image.hpp"

namespace glintlab::test {

struct NdfHistogram {
  std::vector<double> observed;
  int outside = 0;  ///< samples past the bins
};

inline NdfHistogram ndf_histogram(const std::vector<glm::dvec2>& samples, const NdfGrid& grid) {
  const int side = grid.resolution + 1;
  NdfHistogram h{std::vector<double>(static_cast<std::size_t>(side * side), 0.0), 0};
  for (const glm::dvec2& s : samples) {
    const glm::dvec2 g = grid.to_pixels(s) + 0.5;
    const int i = static_cast<int>(std::floor(g.x)), j = static_cast<int>(std::floor(g.y));
    if (i < 0 || j < 0 || i >= side || j >= side) {
      ++h.outside;
      continue;
    }
    h.observed[static_cast<std::size_t>(j * side + i)] += 1;
  }
  return h;
}

inline std::vector<double> ndf_expected_counts(const NdfGrid& grid, std::size_t samples,
                                               const std::function<double(glm::dvec2)>& pdf) {
  const int side = grid.resolution + 1;
  std::vector<double> expected(static_cast<std::size_t>(side * side));
  for (int c = 0; c < side * side; ++c)
    expected[static_cast<std::size_t>(c)] =
        pdf(glm::dvec2(c % side, c / side) * grid.pixel_size() - grid.extent) * grid.pixel_area() * static_cast<double>(samples);
  return expected;
}

}  // namespace glintlab::test
