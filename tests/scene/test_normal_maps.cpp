// Procedural normal maps (src/scene/normal_maps/normal_map.hpp): the fast `bumps` and `brushed` evaluation
// against its definition, the slope statistics they promise, `scratches` against its periodic
// definition and its coverage, `flakes` jitter and flat cells, and progress reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/error.hpp"
#include "scene/normal_maps/bump_waves.hpp"
#include "scene/generation_progress.hpp"
#include "scene/normal_maps/normal_map.hpp"
#include "scene/normal_maps/scratches.hpp"
#include "test_scenes.hpp"

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

namespace {

/// Mean squared slope (b = -n.xy / n.z) along the unit direction `axis`.
double slope_variance_along(const NormalMap& m, glm::vec2 axis) {
  double sum = 0;
  for (const auto& n : m.normals) {
    const double s = (axis.x * n.x + axis.y * n.y) / n.z;
    sum += s * s;
  }
  return sum / static_cast<double>(m.normals.size());
}

glm::vec2 direction(float degrees) {
  return {std::cos(glm::radians(degrees)), std::sin(glm::radians(degrees))};
}

bool same_normals(const NormalMap& a, const NormalMap& b) {
  return a.width == b.width && a.height == b.height && a.normals == b.normals;
}

bool is_flat(glm::vec3 n) { return n == glm::vec3(0.0f, 0.0f, 1.0f); }

double flat_share(const NormalMap& m) {
  return static_cast<double>(std::count_if(m.normals.begin(), m.normals.end(), is_flat)) /
         static_cast<double>(m.normals.size());
}

}  // namespace

TEST(NormalMaps, BrushedSlopeVariancePerAxisIsHalfTheAlphaSquared) {
  // Across the brushing alpha^2 / 2, along it along_alpha^2 / 2 (100 times less here): at an axis
  // and at an angle that mixes u and v.
  for (const float angle : {0.0f, 30.0f}) {
    const NormalMap m = generate_brushed(256, 0.3f, 0.03f, angle, 512, 64, 3);
    const glm::vec2 along = direction(angle), across(-along.y, along.x);
    EXPECT_NEAR(slope_variance_along(m, across), 0.5 * 0.3 * 0.3, 0.1 * 0.5 * 0.3 * 0.3) << angle;
    EXPECT_NEAR(slope_variance_along(m, along), 0.5 * 0.03 * 0.03, 0.25 * 0.5 * 0.03 * 0.03) << angle;
  }
  // The rougher axis may be the brushing one too.
  const NormalMap m = generate_brushed(256, 0.05f, 0.2f, 90.0f, 512, 64, 4);
  EXPECT_NEAR(slope_variance_along(m, {1, 0}), 0.5 * 0.05 * 0.05, 0.25 * 0.5 * 0.05 * 0.05);
  EXPECT_NEAR(slope_variance_along(m, {0, 1}), 0.5 * 0.2 * 0.2, 0.1 * 0.5 * 0.2 * 0.2);
}

TEST(NormalMaps, BrushedIsItsWavesAndDependsOnlyOnItsSeed) {
  const NormalMap a = generate_brushed(64, 0.2f, 0.01f, 20.0f, 128, 16, 5);
  const std::vector<glm::vec3> slow = bump_normals_per_wave(choose_brushed_waves(0.2f, 0.01f, 20.0f, 128, 16, 5), 64);
  float worst = 0.0f;
  for (std::size_t i = 0; i < slow.size(); ++i) worst = std::max(worst, glm::length(a.normals[i] - slow[i]));
  EXPECT_LT(worst, 1e-5f);
  EXPECT_TRUE(same_normals(a, generate_brushed(64, 0.2f, 0.01f, 20.0f, 128, 16, 5)));
  EXPECT_FALSE(same_normals(a, generate_brushed(64, 0.2f, 0.01f, 20.0f, 128, 16, 6)));
  EXPECT_NE(a.description.find("along_alpha=0.01"), std::string::npos) << a.description;
}

TEST(NormalMaps, ScratchHeightsAreTheirPeriodicDefinition) {
  // The rasterised height against its definition: every texel, every scratch, every periodic
  // image near the tile. Long scratches (up to 1.2 tiles) cross the edges and wrap onto themselves.
  ScratchParams p;
  p.resolution = 40;
  p.count = 12;
  p.length = 0.8f;
  p.width = 2.0f;
  p.seed = 11;
  const std::vector<Scratch> scratches = choose_scratches(p);
  const GrooveProfile profile = groove_profile(p.width, p.slope);
  const std::vector<float> fast = scratch_heights(p, scratches, profile);
  const float n = static_cast<float>(p.resolution);
  float worst = 0.0f, deepest = 0.0f;
  for (int y = 0; y < p.resolution; ++y)
    for (int x = 0; x < p.resolution; ++x) {
      double h = 0.0;
      for (const Scratch& s : scratches)
        for (int iy = -2; iy <= 2; ++iy)
          for (int ix = -2; ix <= 2; ++ix) {
            const glm::vec2 q = glm::vec2(x + 0.5f, y + 0.5f) + n * glm::vec2(ix, iy), ab = s.to - s.from;
            const float t = std::clamp(glm::dot(q - s.from, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
            h -= profile(glm::length(q - (s.from + t * ab)));
          }
      const float got = fast[static_cast<std::size_t>(y) * p.resolution + x];
      worst = std::max(worst, std::abs(got - static_cast<float>(h)));
      deepest = std::max(deepest, -got);
    }
  EXPECT_LT(worst, 1e-5f * profile.depth);
  EXPECT_GT(deepest, 0.9f * profile.depth);  // the test saw grooves
}

TEST(NormalMaps, AScratchsSteepestWallIsItsSlope) {
  ScratchParams p;
  p.resolution = 64;
  p.count = 1;
  p.angle_spread = 0.0f;
  // Along u: slopes in v only. The texel centres sample the wall's central differences at one
  // offset, below their largest by more the narrower the groove.
  for (const auto [width, least] : {std::pair{0.5f, 0.7f}, std::pair{1.5f, 0.9f}, std::pair{4.0f, 0.97f}}) {
    p.width = width;
    const NormalMap m = generate_scratches(p);
    float steepest = 0.0f;
    for (const auto& nrm : m.normals) steepest = std::max(steepest, std::abs(nrm.y / nrm.z));
    EXPECT_LE(steepest, p.slope * 1.0001f) << width;
    EXPECT_GE(steepest, p.slope * least) << width;
  }
}

TEST(NormalMaps, MoreAndWiderScratchesCoverMoreOfTheMap) {
  // Covered: a slope of at least 5% of the walls' steepest.
  ScratchParams p;
  p.resolution = 128;
  auto covered = [&](int count, float width) {
    p.count = count;
    p.width = width;
    const NormalMap m = generate_scratches(p);
    std::size_t sloped = 0;
    for (const auto& nrm : m.normals) {
      EXPECT_NEAR(glm::length(nrm), 1.0f, 1e-5f);
      EXPECT_GT(nrm.z, 0.0f);
      sloped += glm::length(glm::vec2(nrm) / nrm.z) >= 0.05f * p.slope;
    }
    return static_cast<double>(sloped) / static_cast<double>(m.normals.size());
  };
  const double few = covered(5, 1.0f), many = covered(20, 1.0f), wide = covered(20, 3.0f);
  EXPECT_GT(few, 0.0);
  EXPECT_GT(many, 2.0 * few);
  EXPECT_GT(wide, 1.5 * many);
  EXPECT_LT(wide, 0.9);
}

TEST(NormalMaps, ScratchesTileAndDependOnlyOnTheirSeed) {
  ScratchParams p;
  p.resolution = 64;
  p.count = 60;
  p.length = 0.5f;
  const NormalMap m = generate_scratches(p);
  // Normals change across the wrap (column n-1 to column 0, row n-1 to row 0) as much as between
  // neighbours inside: a groove cut at the edge would jump there.
  auto step = [&](int x0, int y0, int x1, int y1) {
    const int n = p.resolution;
    const auto at = [&](int x, int y) { return m.normals[static_cast<std::size_t>(y) * n + x]; };
    return glm::length(at(x0, y0) - at(x1, y1));
  };
  double inside = 0.0, seam = 0.0;
  for (int i = 0; i < p.resolution; ++i) {
    seam += step(p.resolution - 1, i, 0, i) + step(i, p.resolution - 1, i, 0);
    for (int j = 0; j + 1 < p.resolution; ++j) inside += step(j, i, j + 1, i) + step(i, j, i, j + 1);
  }
  inside /= p.resolution - 1;
  EXPECT_GT(seam, 0.0);
  EXPECT_LT(seam, 2.0 * inside);
  EXPECT_GT(seam, 0.5 * inside);
  EXPECT_TRUE(same_normals(m, generate_scratches(p)));
  p.seed = 2;
  EXPECT_FALSE(same_normals(m, generate_scratches(p)));
}

TEST(NormalMaps, ScratchesOnABaseAddTheirSlopesToTheBumps) {
  ScratchParams p;
  p.resolution = 64;
  p.count = 0;
  p.base_alpha = 0.3f;
  const NormalMap base = generate_bumps(64, 0.3f, 128, 24, p.seed);
  float worst = 0.0f;
  const NormalMap bare = generate_scratches(p);
  for (std::size_t i = 0; i < base.normals.size(); ++i)
    worst = std::max(worst, glm::length(bare.normals[i] - base.normals[i]));
  EXPECT_LT(worst, 1e-6f);
  p.count = 30;
  const NormalMap scratched = generate_scratches(p);
  p.base_alpha = 0.0f;
  const NormalMap alone = generate_scratches(p);
  for (std::size_t i = 0; i < base.normals.size(); i += 7) {
    const glm::vec2 sum =
        glm::vec2(base.normals[i]) / base.normals[i].z + glm::vec2(alone.normals[i]) / alone.normals[i].z;
    const glm::vec2 got = glm::vec2(scratched.normals[i]) / scratched.normals[i].z;
    EXPECT_LT(glm::length(got - sum), 1e-4f) << i;
  }
}

TEST(NormalMaps, FlakesFlatFractionFlattensWholeCellsAndLeavesTheOthers) {
  const NormalMap none = generate_flakes(64, 16, 0.3f, 5);
  EXPECT_TRUE(same_normals(none, generate_flakes(64, 16, 0.3f, 5, 1.0f, 0.0f)));  // the defaults
  EXPECT_EQ(flat_share(none), 0.0);
  const NormalMap some = generate_flakes(64, 16, 0.3f, 5, 1.0f, 0.3f);
  const NormalMap more = generate_flakes(64, 16, 0.3f, 5, 1.0f, 0.6f);
  EXPECT_NEAR(flat_share(some), 0.3, 0.1);
  EXPECT_NEAR(flat_share(more), 0.6, 0.1);
  for (std::size_t i = 0; i < none.normals.size(); ++i) {
    if (!is_flat(some.normals[i])) EXPECT_EQ(some.normals[i], none.normals[i]) << i;
    if (is_flat(some.normals[i])) EXPECT_TRUE(is_flat(more.normals[i])) << i;
  }
  EXPECT_EQ(flat_share(generate_flakes(32, 8, 0.3f, 5, 1.0f, 1.0f)), 1.0);
}

TEST(NormalMaps, FlakesWithoutJitterAreTheGridsSquares) {
  // Feature points at the cell centres: the Voronoi cells are the 4x4-texel squares of the grid.
  auto squares_are_uniform = [](const NormalMap& m) {
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x)
        if (m.normals[static_cast<std::size_t>(y) * m.width + x] !=
            m.normals[static_cast<std::size_t>(y / 4 * 4) * m.width + x / 4 * 4])
          return false;
    return true;
  };
  EXPECT_TRUE(squares_are_uniform(generate_flakes(64, 16, 0.3f, 2, 0.0f)));
  EXPECT_FALSE(squares_are_uniform(generate_flakes(64, 16, 0.3f, 2, 0.5f)));
  EXPECT_FALSE(squares_are_uniform(generate_flakes(64, 16, 0.3f, 2)));
}

namespace {

Scene scene_with_map(const test::TomlKeys& map) {
  return test::TestScene().material("m", {{"normal_map", map}}).sphere("m").point_light({0, 2, 3}).scene();
}

std::string scene_error(const test::TomlKeys& map) {
  try {
    static_cast<void>(scene_with_map(map));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

}  // namespace

TEST(NormalMaps, SceneKeysMakeTheMapsTheirDescriptionsName) {
  const auto map_of = [](const test::TomlKeys& keys) { return *scene_with_map(keys).materials.at(0).normal_map; };
  const NormalMap noise = map_of({{"generator", "noise"}, {"resolution", 16}, {"max_frequency", 4}});
  const NormalMap bumps = map_of({{"generator", "bumps"}, {"resolution", 16}, {"max_frequency", 4}});
  EXPECT_TRUE(same_normals(noise, bumps));
  EXPECT_EQ(noise.description, bumps.description);  // one map, one name
  EXPECT_TRUE(same_normals(map_of({{"generator", "brushed"}, {"resolution", 32}, {"angle", 10.0}}),
                           generate_brushed(32, 0.2f, 0.01f, 10.0f, 512, 8, 1)));
  ScratchParams p;
  p.resolution = 32;
  p.count = 7;
  p.angle_spread = 20.0f;
  const NormalMap scratches =
      map_of({{"generator", "scratches"}, {"resolution", 32}, {"count", 7}, {"angle_spread", 20.0}});
  EXPECT_TRUE(same_normals(scratches, generate_scratches(p)));
  EXPECT_EQ(scratches.description, describe(p));
  for (const char* key : {"count=7", "length=0.25", "width=1.5", "slope=0.4", "angle=0", "angle_spread=20",
                          "base_alpha=0", "seed=1"})
    EXPECT_NE(scratches.description.find(key), std::string::npos) << key << " not in " << scratches.description;
  EXPECT_TRUE(same_normals(map_of({{"generator", "flakes"}, {"resolution", 32}, {"cells", 8}, {"jitter", 0.5},
                                   {"flat_fraction", 0.25}}),
                           generate_flakes(32, 8, 0.2f, 1, 0.5f, 0.25f)));
}

TEST(NormalMaps, GeneratorKeysOutOfRangeNameKeyValueAndRange) {
  struct Case {
    test::TomlKeys map;
    const char* key;
    const char* value;
  };
  for (const Case& c : {Case{{{"generator", "scratches"}, {"angle_spread", 200.0}}, "angle_spread", "200"},
                        Case{{{"generator", "scratches"}, {"width", 0.1}}, "width", "0.1"},
                        Case{{{"generator", "scratches"}, {"count", -1}}, "count", "-1"},
                        Case{{{"generator", "brushed"}, {"along_alpha", -0.5}}, "along_alpha", "-0.5"},
                        Case{{{"generator", "brushed"}, {"resolution", 64}, {"max_frequency", 33}}, "max_frequency",
                             "33"},
                        Case{{{"generator", "flakes"}, {"jitter", 1.5}}, "jitter", "1.5"},
                        Case{{{"generator", "flakes"}, {"flat_fraction", 2.0}}, "flat_fraction", "2"},
                        Case{{{"generator", "bumps"}, {"along_alpha", 0.1}}, "along_alpha", ""},
                        Case{{{"generator", "waves"}}, "generator", "brushed"}}) {
    const std::string message = scene_error(c.map);
    for (const char* part : {"test.toml", c.key, c.value})
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}
