// The split-sum prefilter of an environment map (src/scene/lights/environment_prefilter.hpp):
// furnace tests (a uniform map stays itself at every specular level; its irradiance is pi L) and
// the irradiance of one bright texel against L Omega cos.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/lights/environment_map.hpp"
#include "scene/lights/environment_prefilter.hpp"

using namespace glintlab;

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

TEST(EnvironmentPrefilter, LevelSizesHalveFromTheBaseDownToTheMinimum) {
  const std::vector<Image> levels = prefilter_environment_specular(Image(512, 256, glm::vec3(1.0f)));
  ASSERT_EQ(levels.size(), std::size_t{kEnvironmentSpecularLevels});
  const int widths[] = {256, 128, 64, 32, 16, 8};
  for (int m = 0; m < kEnvironmentSpecularLevels; ++m) {
    EXPECT_EQ(levels[static_cast<std::size_t>(m)].width(), widths[m]) << m;
    EXPECT_EQ(levels[static_cast<std::size_t>(m)].height(), widths[m] / 2) << m;
  }
  EXPECT_EQ(environment_specular_width(64, 5), kEnvironmentSpecularMinWidth);
  EXPECT_EQ(environment_specular_alpha(0), 0.0);
  EXPECT_NEAR(environment_specular_alpha(1), 0.04, 1e-15);
  EXPECT_EQ(environment_specular_alpha(kEnvironmentSpecularLevels - 1), 1.0);
}

TEST(EnvironmentPrefilter, AUniformMapIsItselfAtEveryLevel) {
  const glm::vec3 radiance(0.25f, 1.0f, 3.0f);
  const PrefilteredEnvironment p = prefilter_environment(uniform_environment_map(radiance).radiance);
  for (std::size_t m = 0; m < p.specular_levels.size(); ++m)
    for (const glm::vec3& texel : p.specular_levels[m].pixels())
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(texel[c], radiance[c], 1e-5 * radiance[c]) << "level " << m;
  ASSERT_EQ(p.irradiance.width(), kEnvironmentIrradianceWidth);
  ASSERT_EQ(p.irradiance.height(), kEnvironmentIrradianceWidth / 2);
  for (const glm::vec3& texel : p.irradiance.pixels())
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(texel[c], kPi * radiance[c], 1e-4 * kPi * radiance[c]);
}

TEST(EnvironmentPrefilter, IrradianceOfOneBrightTexelIsLOmegaCos) {
  constexpr int kWidth = kEnvironmentIrradianceSourceWidth;
  const int hot_x = 40, hot_y = 10;
  const float hot = 1000.0f;
  Image map(kWidth, kWidth / 2);
  map.at(hot_x, hot_y) = glm::vec3(hot);
  const Image e = environment_irradiance(map);
  const glm::dvec3 centre = environment_direction_precise((hot_x + 0.5) / kWidth, (hot_y + 0.5) / (kWidth / 2));
  const double omega = environment_row_solid_angle(hot_y, kWidth / 2);
  int lit = 0;
  for (int y = 0; y < e.height(); ++y)
    for (int x = 0; x < e.width(); ++x) {
      const glm::dvec3 n = environment_direction_precise((x + 0.5) / e.width(), (y + 0.5) / e.height());
      const double cos_n = glm::dot(n, centre);
      const double expected = hot * omega * std::max(0.0, cos_n);
      if (std::abs(cos_n) < 0.1) continue;  // the horizon crosses the texel: only partly lit
      EXPECT_NEAR(e.at(x, y).g, expected, 0.01 * hot * omega) << x << ", " << y << ": cos " << cos_n;
      lit += cos_n > 0;
    }
  EXPECT_GT(lit, 100);
}

TEST(EnvironmentPrefilter, ABrightTexelBlursIntoALobeAboutItsDirection) {
  Image map(256, 128, glm::vec3(0.01f));
  map.at(70, 40) = glm::vec3(5000.0f);
  const glm::dvec3 spot = environment_direction_precise(70.5 / 256, 40.5 / 128);
  const std::vector<Image> levels = prefilter_environment_specular(map);
  for (int m = 1; m < kEnvironmentSpecularLevels; ++m) {
    const Image& level = levels[static_cast<std::size_t>(m)];
    int best_x = 0, best_y = 0;
    double total = 0;
    for (int y = 0; y < level.height(); ++y)
      for (int x = 0; x < level.width(); ++x) {
        total += level.at(x, y).r * environment_row_solid_angle(y, level.height());
        if (level.at(x, y).r > level.at(best_x, best_y).r) best_x = x, best_y = y;
      }
    const glm::dvec3 peak =
        environment_direction_precise((best_x + 0.5) / level.width(), (best_y + 0.5) / level.height());
    // The peak lies within a texel's diagonal of the spot (level 5's lobe is the cosine: wide).
    EXPECT_GT(glm::dot(peak, spot), std::cos(2.0 * kPi / level.height())) << "level " << m;
    // The kernel depends on r.l alone, so the convolution keeps the power: the spot's is spread,
    // not lost to samples that miss it nor multiplied by samples that all hit it.
    const double spot_power = (5000.0 - 0.01) * environment_row_solid_angle(40, 128);
    EXPECT_NEAR(total - 0.01 * 4 * kPi, spot_power, 0.1 * spot_power) << "level " << m;
  }
}
