#pragma once
// Comparing a glint render with the smooth render it converges to (dense glints), shared by the
// glint methods' tests: means over the image and over 8x8-pixel blocks.
#include <gtest/gtest.h>

#include <string>

#include "core/image.hpp"
#include "core/metrics.hpp"

namespace glintlab::test {

inline double mean_luminance(const Image& img) { return luminance(glm::vec3(img.mean())); }

inline double block_mean(const Image& img, int x0, int y0, int n) {
  double sum = 0;
  for (int y = y0; y < y0 + n; ++y)
    for (int x = x0; x < x0 + n; ++x) sum += luminance(img.at(x, y));
  return sum / (n * n);
}

/// Mean within 2%, and each 8x8-pixel block where the lobe is (above 5% of the mean) within 6%,
/// of the smooth render.
inline void expect_matches_smooth(const Image& glints, const Image& smooth, const std::string& what) {
  const double g = mean_luminance(glints), c = mean_luminance(smooth);
  EXPECT_NEAR(g, c, 0.02 * c) << what;
  for (int by = 0; by + 8 <= glints.height(); by += 8)
    for (int bx = 0; bx + 8 <= glints.width(); bx += 8) {
      const double gb = block_mean(glints, bx, by, 8), cb = block_mean(smooth, bx, by, 8);
      if (cb > 0.05 * c) {
        EXPECT_NEAR(gb, cb, 0.06 * cb) << what << " block " << bx << ", " << by;
      }
    }
}

}  // namespace glintlab::test
