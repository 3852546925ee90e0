// Procedural normal maps (src/scene/normal_map.hpp): the fast `bumps` evaluation against its
// definition, the slope statistics it promises, and progress reports of slow generation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/bump_waves.hpp"
#include "scene/generation_progress.hpp"
#include "scene/normal_map.hpp"

using namespace glintlab;

namespace {

struct BumpCase {
  int resolution, waves, max_frequency;
  float anisotropy, angle;
};

double slope_variance(const NormalMap& m) {
  double sum = 0;
  for (const auto& n : m.normals) sum += (n.x * n.x + n.y * n.y) / (n.z * n.z);
  return sum / static_cast<double>(m.normals.size());
}

}  // namespace

TEST(NormalMaps, BumpsEqualTheirWaveByWaveSum) {
  // Power-of-two and other resolutions (radix-2 and Bluestein row sums), anisotropic waves, and
  // frequencies up to resolution / 2, where +k and -k share a row bin.
  for (const BumpCase c : {BumpCase{64, 64, 12, 1.0f, 0.0f}, BumpCase{96, 200, 20, 6.0f, 45.0f},
                           BumpCase{50, 300, 25, 1.0f, 0.0f}, BumpCase{33, 40, 16, 3.0f, -30.0f},
                           BumpCase{4, 3, 2, 1.0f, 0.0f}}) {
    const NormalMap fast = generate_bumps(c.resolution, 0.4f, c.waves, c.max_frequency, 7, c.anisotropy, c.angle);
    const std::vector<glm::vec3> slow = bump_normals_per_wave(
        choose_bump_waves(0.4f, c.waves, c.max_frequency, 7, c.anisotropy, c.angle), c.resolution);
    ASSERT_EQ(fast.normals.size(), slow.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < slow.size(); ++i)
      for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(fast.normals[i][a] - slow[i][a]));
    EXPECT_LT(worst, 1e-5f) << "resolution " << c.resolution << ", waves " << c.waves;
  }
}

TEST(NormalMaps, BumpsHaveTheRequestedSlopeSpread) {
  // Slope variance over both axes = alpha^2 (Beckmann convention): exact over the tile for
  // orthogonal waves, up to sampling at the texels.
  EXPECT_NEAR(slope_variance(generate_bumps(128, 0.3f, 64, 12, 5)), 0.09, 0.01);
  EXPECT_NEAR(slope_variance(generate_bumps(256, 0.5f, 1000, 100, 2, 4.0f, 30.0f)), 0.25, 0.025);
  EXPECT_NEAR(slope_variance(generate_bumps(512, 0.2f, 4096, 200, 9)), 0.04, 0.004);
}

TEST(NormalMaps, BumpsAskedForMoreWavesThanFrequenciesKeepTheDistinctOnes) {
  // max_frequency 2 has a handful of distinct integer frequencies: the rest are not repeats.
  const BumpSpectrum s = choose_bump_waves(0.3f, 4096, 2, 1, 1.0f, 0.0f);
  EXPECT_LT(s.waves.size(), 20u);
  for (std::size_t i = 0; i < s.waves.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_TRUE(s.waves[i].k != s.waves[j].k && s.waves[i].k != -s.waves[j].k);
}

TEST(NormalMaps, GenerationReportsRowsToTheObserverOfItsThread) {
  std::vector<std::pair<int, int>> reports;
  std::string what;
  {
    const ScopedGenerationObserver observer([&](const std::string& w, int done, int total) {
      what = w;
      reports.emplace_back(done, total);
    });
    static_cast<void>(generate_bumps(256, 0.3f, 32, 8, 1));
  }
  ASSERT_FALSE(reports.empty());
  EXPECT_NE(what.find("bumps(resolution=256"), std::string::npos) << what;
  EXPECT_EQ(reports.front(), std::make_pair(0, 256));
  EXPECT_EQ(reports.back(), std::make_pair(256, 256));
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  const auto count = reports.size();
  static_cast<void>(generate_bumps(64, 0.3f, 8, 4, 1));  // the scope ended: nobody is told
  EXPECT_EQ(reports.size(), count);
}
