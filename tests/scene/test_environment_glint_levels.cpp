// The environment's luminance levels for glints under image-based lighting
// (src/scene/lights/environment_glint_levels.hpp): the levels log-spaced between the dimmest lit
// texel and the brightest; the tent weights a partition of unity that reproduces each texel's
// luminance; and, prefiltered by the radiance's own chain, the weights still reproduce the
// prefiltered radiance's luminance at every texel of every level.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/lights/environment_glint_levels.hpp"
#include "scene/lights/environment_prefilter.hpp"

using namespace glintlab;

namespace {

// A sky of smooth luminance with a few small, very bright texels (a sun and lamps) and black ones.
Image test_sky(int width, int height) {
  Image sky(width, height);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      sky.at(x, y) = glm::vec3(0.2f + 0.3f * u(rng), 0.3f, 0.5f) * (y < height / 2 ? 1.0f : 0.02f);
  sky.at(width / 3, height / 4) = glm::vec3(2000.0f, 1900.0f, 1800.0f);
  sky.at(2 * width / 3, height / 3) = glm::vec3(40.0f);
  for (int x = 0; x < width; x += 7) sky.at(x, height - 1) = glm::vec3(0.0f);
  return sky;
}

TEST(EnvironmentGlintLevels, LevelsAreLogSpacedAndTheWeightsReproduceEachTexelsLuminance) {
  const Image sky = test_sky(128, 64);
  const EnvironmentGlintLevels levels = environment_glint_levels(sky);
  const auto& L = levels.luminance;
  EXPECT_EQ(L[0], 0.0f);
  EXPECT_FLOAT_EQ(L[3], luminance(glm::vec3(2000.0f, 1900.0f, 1800.0f)));
  // L_2 / L_1 = L_3 / L_2: one ratio between consecutive levels.
  EXPECT_NEAR(std::log(L[2] / L[1]), std::log(L[3] / L[2]), 1e-5);
  for (std::size_t i = 0; i < sky.pixel_count(); ++i) {
    const glm::vec3 w = levels.weights.pixels()[i];
    const float w0 = 1.0f - w.r - w.g - w.b;
    ASSERT_GE(std::min({w0, w.r, w.g, w.b}), -1e-6f) << i;
    const float y = luminance(sky.pixels()[i]);
    ASSERT_NEAR(L[1] * w.r + L[2] * w.g + L[3] * w.b, y, 1e-5f * std::max(y, 1.0f)) << i;
  }
  // A black map: everything level 0.
  const EnvironmentGlintLevels black = environment_glint_levels(Image(8, 4));
  for (const glm::vec3& w : black.weights.pixels()) EXPECT_EQ(w, glm::vec3(0.0f));
}

TEST(EnvironmentGlintLevels, PrefilteredWeightsReproduceThePrefilteredLuminance) {
  // The identity the method's brightness rests on: the same linear filter on both.
  const Image sky = test_sky(256, 128);
  const EnvironmentGlintLevels levels = environment_glint_levels(sky);
  const std::vector<Image> radiance = prefilter_environment_specular(sky);
  const std::vector<Image> weights = prefilter_environment_specular(levels.weights);
  ASSERT_EQ(radiance.size(), weights.size());
  for (std::size_t m = 0; m < radiance.size(); ++m)
    for (std::size_t i = 0; i < radiance[m].pixel_count(); ++i) {
      const glm::vec3 w = weights[m].pixels()[i];
      const float y = luminance(radiance[m].pixels()[i]);
      ASSERT_NEAR(levels.luminance[1] * w.r + levels.luminance[2] * w.g + levels.luminance[3] * w.b, y,
                  1e-4f * std::max(y, 1e-3f))
          << "level " << m << " texel " << i;
      ASSERT_LE(w.r + w.g + w.b, 1.0f + 1e-5f);
    }
}

}  // namespace
