// Deng et al. 2022's prefiltered NDF pyramid on the CPU (src/prefilter/): its queries against the
// NDF images it compresses and against brute-force sums, its mass, continuity, limits and cache.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "core/cache_entry.hpp"
#include "core/error.hpp"
#include "prefilter/box_prefix_tables.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "small_pyramid_settings.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/prefilter_cache.hpp"
#include "prefilter/prefilter_params.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"
#include "scratch_directory.hpp"

namespace glintlab {
namespace {

PrefilterSettings small_settings() { return test::small_pyramid_settings(); }

const NormalMap& bumps() {
  static const NormalMap map = generate_bumps(32, 0.25f, 48, 6, 9);
  return map;
}
const PrefilteredNdf& pyramid() {
  static const PrefilteredNdf p = precompute_prefiltered_ndf(bumps(), 0.03, small_settings());
  return p;
}

TEST(PrefilteredNdf, StoredFootprintsQueryTheirOwnImages) {
  // At a stored footprint's centre and sigma, the point query at a pixel centre is that pixel.
  const PrefilteredNdf& p = pyramid();
  for (std::size_t l = 0; l < p.levels.size(); ++l) {
    const PrefilterLevel& level = p.levels[l];
    const int x = level.nx / 2, y = level.ny - 1;
    const std::uint32_t f = level.first_footprint + static_cast<std::uint32_t>(y * level.nx + x);
    const glm::dvec2 centre = (glm::dvec2(x, y) + 0.5) * level.spacing;
    for (auto [i, j] : {std::pair{3, 5}, {16, 16}, {20, 9}})
      EXPECT_NEAR(p.density(centre, level.sigma, p.grid.pixel_centre(i, j)), p.pixel(f, i, j), 1e-5)
          << "level " << l;
  }
}

TEST(PrefilteredNdf, CompressedImagesStayCloseToYansAndHoldTheMass) {
  // Each stored image against Yan 2016's image of the same footprint: the CP compression's error
  // (measured, per level) bounds it, and the mass stays 1 within that error.
  const PrefilteredNdf& p = pyramid();
  const PositionNormalDistribution pnd(bumps(), 0.03, p.settings.elements_per_texel);
  for (std::size_t l = 0; l < p.levels.size(); ++l) {
    const PrefilterLevel& level = p.levels[l];
    const int x = (level.nx * 2) / 3, y = level.ny / 3;
    const std::uint32_t f = level.first_footprint + static_cast<std::uint32_t>(y * level.nx + x);
    const NdfImage yan = pnd.image(Footprint::isotropic((glm::dvec2(x, y) + 0.5) * level.spacing, level.sigma), p.grid);
    const NdfImage ours = p.image(f);
    const double error = relative_l2(ours, yan);
    std::printf("level %zu (sigma %.0f texels): compression error %.4f, this image %.4f, mass %.4f vs %.4f\n", l,
                level.sigma, level.compression_error, error, ours.mass(), yan.mass());
    EXPECT_LT(error, 3.0 * level.compression_error + 0.02) << "level " << l;
    EXPECT_NEAR(ours.mass(), yan.mass(), 2.0 * level.compression_error) << "level " << l;
    EXPECT_NEAR(yan.mass(), 1.0, 1e-3);
  }
}

TEST(PrefilteredNdf, RangeQueriesEqualBruteForceSums) {
  const PrefilteredNdf& p = pyramid();
  const PrefilterLevel& level = p.levels[1];
  const std::uint32_t f = level.first_footprint + 3;
  // Whole pixels: the sum of the reconstructed pixels; fractional: their piecewise-constant integral.
  for (auto [x0, x1, y0, y1] : {std::array{2.0, 13.0, 5.0, 30.0}, {7.25, 7.75, 0.5, 31.5}, {0.0, 32.0, 0.0, 32.0},
                                {15.5, 17.25, 6.0, 25.0}}) {
    double brute = 0.0;
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) {
        const double cover = std::max(0.0, std::min(x1, i + 1.0) - std::max(x0, double(i))) *
                             std::max(0.0, std::min(y1, j + 1.0) - std::max(y0, double(j)));
        brute += cover * p.pixel(f, i, j);
      }
    EXPECT_NEAR(p.pixel_range_sum(f, {x0, y0}, {x1, y1}), brute, 1e-4 * (1.0 + std::abs(brute)));
  }
}

TEST(PrefilteredNdf, QueriesAreContinuousAcrossBlocksAndLevels) {
  const PrefilteredNdf& p = pyramid();
  const glm::dvec2 centre(11.3, 20.7);
  // Across a block edge (pixel 8 of 32 over [-extent, extent]) the point query moves by no more
  // than its local slope allows.
  const double edge = -p.grid.extent + 8 * p.grid.pixel_size();
  for (double t : {-0.1, 0.0, 0.12}) {
    const glm::dvec2 a(edge - 1e-6, t), b(edge + 1e-6, t);
    const double va = p.density(centre, 2.0, a), vb = p.density(centre, 2.0, b);
    EXPECT_NEAR(va, vb, 1e-3 * (1.0 + va));
  }
  // Across a level (sigma = 2 sigma_0 is a level's own) and across footprint centres.
  const double s0 = p.levels[0].sigma;
  for (double sigma : {2 * s0, 4 * s0}) {
    const double below = p.density(centre, sigma * (1 - 1e-7), {0.02, -0.03});
    const double above = p.density(centre, sigma * (1 + 1e-7), {0.02, -0.03});
    EXPECT_NEAR(below, above, 1e-4 * (1.0 + below));
  }
  const glm::dvec2 on_centre = 1.5 * p.levels[0].spacing;
  EXPECT_NEAR(p.density(on_centre - 1e-7, s0, {0.0, 0.0}), p.density(on_centre + 1e-7, s0, {0.0, 0.0}), 1e-4);
}

// The queries against the exact P-NDF of the same elements (src/prefilter/position_normal.hpp, an
// independent sum, no image, no compression): box means over 1 to 8 NDF pixels and point densities,
// at stored footprints (the compression and the angular grid's error) and between them, at random
// centres and sigmas across levels (plus the trilinear interpolation's). Relative L2 over the
// queries, bounded near the measured values (in the comments).
struct QueryErrors {
  double on_box, on_point, between_box, between_point;
};

QueryErrors query_errors(const PrefilteredNdf& p) {
  const PositionNormalDistribution exact(bumps(), 0.03, p.settings.elements_per_texel);
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e = p.grid.extent, pixel = p.grid.pixel_size();
  struct Errors {
    double box2 = 0, box_truth2 = 0, point2 = 0, point_truth2 = 0;
    [[nodiscard]] double box() const { return std::sqrt(box2 / box_truth2); }
    [[nodiscard]] double point() const { return std::sqrt(point2 / point_truth2); }
  };
  Errors on, between;
  for (int f = 0; f < 48; ++f) {
    const bool stored = f % 2 == 0;
    glm::dvec2 centre;
    double sigma;
    if (stored) {  // a stored footprint of levels 0 .. 2
      const PrefilterLevel& level = p.levels[static_cast<std::size_t>(f / 2 % std::min<std::size_t>(3, p.levels.size()))];
      centre = (glm::dvec2(std::floor(u(rng) * level.nx), std::floor(u(rng) * level.ny)) + 0.5) * level.spacing;
      sigma = level.sigma;
    } else {
      centre = {32.0 * u(rng), 32.0 * u(rng)};
      sigma = p.levels[0].sigma * std::exp2(2.0 * u(rng));
    }
    Errors& errors = stored ? on : between;
    const Footprint footprint = Footprint::isotropic(centre, sigma);
    for (int q = 0; q < 24; ++q) {
      const glm::dvec2 s(e * (1.2 * u(rng) - 0.6), e * (1.2 * u(rng) - 0.6));
      const glm::dvec2 half = 0.5 * pixel * glm::dvec2(1.0 + 7.0 * u(rng), 1.0 + 7.0 * u(rng));
      const double box = exact.range_mean(footprint, s - half, s + half);
      const double ours_box = p.range_mean(centre, sigma, s - half, s + half);
      errors.box2 += (ours_box - box) * (ours_box - box);
      errors.box_truth2 += box * box;
      const double point = exact.density(footprint, s), ours_point = p.density(centre, sigma, s);
      errors.point2 += (ours_point - point) * (ours_point - point);
      errors.point_truth2 += point * point;
    }
  }
  return {on.box(), on.point(), between.box(), between.point()};
}

TEST(PrefilteredNdf, QueriesApproachTheExactNdfOnAndBetweenStoredFootprints) {
  // The angular grid (32^2 pixels over [-extent, extent]^2, each about sigma_r wide) dominates the
  // point query's error, which the grid chosen from sigma_r (ndf_resolution 0: pixels at most
  // sigma_r / 2, issue 30 item 5) more than halves; the box query averages it away.
  PrefilterSettings fine = small_settings();
  fine.ndf_resolution = 0;
  fine.block_size = 0;
  const PrefilteredNdf chosen = precompute_prefiltered_ndf(bumps(), 0.03, fine);
  EXPECT_LE(chosen.grid.pixel_size(), 0.015);
  EXPECT_GT(chosen.grid.pixel_size(), 0.0075);  // the smallest such grid (N a multiple of 16)
  EXPECT_EQ(chosen.blocks_per_side(), 4);
  const QueryErrors coarse = query_errors(pyramid()), finer = query_errors(chosen);
  const std::string chosen_name = std::to_string(chosen.grid.resolution) + "^2";
  for (const auto& [name, q] : {std::pair{std::string("32^2"), coarse}, {chosen_name, finer}})
    std::printf("%s NDF pixels, relative L2 to the exact P-NDF: stored footprints box %.4f point %.4f; between "
                "them box %.4f point %.4f\n", name.c_str(), q.on_box, q.on_point, q.between_box, q.between_point);
  EXPECT_LT(coarse.on_box, 0.06);  // measured 0.045
  EXPECT_LT(coarse.between_box, 0.13);  // 0.101: the trilinear interpolation's share
  EXPECT_LT(coarse.on_point, 0.22);  // 0.179
  EXPECT_LT(coarse.between_point, 0.22);  // 0.169
  // Measured (112^2 pixels in 28^2 blocks): point 0.072 on, 0.124 between (where the trilinear
  // interpolation's share remains); box 0.056 and 0.113, rank 4 fitting larger blocks.
  EXPECT_LT(finer.on_point, 0.5 * coarse.on_point);
  EXPECT_LT(finer.between_point, 0.85 * coarse.between_point);
  EXPECT_LT(finer.on_box, 1.5 * coarse.on_box);
}

// `decomposition = als` (the paper's unconstrained ALS, 500 sweeps) against the default nonnegative
// HALS at the same rank on the same groups: a lower compression error on every level with more than
// a handful of blocks, values that may dip below 0 in the factors but never in a query. The
// parameters parse in any order (the decomposition's reset comes first).
TEST(PrefilteredNdf, AlsCompressesCloserThanHalsAndItsQueriesStayNonnegative) {
  const PrefilterSettings als = prefilter_settings_from({{"rank", 8.0f}, {"decomposition", 1.0f}, {"ndf_resolution", 32.0f},
                                                         {"block_size", 8.0f}, {"base_stride", 1.0f}});
  ASSERT_FALSE(als.cp.nonnegative);
  ASSERT_EQ(als.cp.max_iterations, 500);
  ASSERT_EQ(als.cp.rank, 8);
  PrefilterSettings hals = als;
  hals.cp = PrefilterSettings::kHals;
  hals.cp.rank = 8;
  const PrefilteredNdf a = precompute_prefiltered_ndf(bumps(), 0.03, als), h = precompute_prefiltered_ndf(bumps(), 0.03, hals);
  ASSERT_EQ(a.levels.size(), h.levels.size());
  for (std::size_t l = 0; l < a.levels.size(); ++l) {
    std::printf("level %zu: compression error ALS %.4f, HALS %.4f\n", l, a.levels[l].compression_error,
                h.levels[l].compression_error);
    if (l < 3) {
      EXPECT_LT(a.levels[l].compression_error, 0.95 * h.levels[l].compression_error) << "level " << l;
    }
  }
  bool negative_factor = false;
  for (float v : a.rows) negative_factor |= v < 0.0f;
  for (float v : a.angular) negative_factor |= v < 0.0f;
  EXPECT_TRUE(negative_factor) << "ALS is unconstrained";
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e = a.grid.extent;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec2 c(32.0 * u(rng), 32.0 * u(rng)), s(e * (2 * u(rng) - 1), e * (2 * u(rng) - 1));
    const double sigma = std::exp2(3.0 * u(rng));
    ASSERT_GE(a.density(c, sigma, s), 0.0);
    ASSERT_GE(a.range_mean(c, sigma, s, s + 0.1 * e), 0.0);
  }
}

TEST(PrefilteredNdf, OneTexelFootprintWithoutRoughnessSeesTheTexelsNormal) {
  // A map of flat facets about 8 texels wide (flakes), the finest footprint (sigma one texel) inside
  // a facet, sigma_r tiny: the query's NDF concentrates at that facet's normal.
  const NormalMap map = generate_flakes(32, 4, 0.2f, 2);
  PrefilterSettings s = small_settings();
  s.ndf_resolution = 64;
  const PrefilteredNdf p = precompute_prefiltered_ndf(map, 0.002, s);
  const PrefilterLevel& level = p.levels[0];
  int checked = 0;
  for (int y = 0; y < level.ny; ++y)
    for (int x = 0; x < level.nx; ++x) {
      const glm::ivec2 t(x, y);
      const glm::vec3 n = map.normals[static_cast<std::size_t>(t.y * map.width + t.x)];
      bool interior = true;  // every texel within 3 sigma shares the normal
      for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx)
          interior = interior && map.normals[static_cast<std::size_t>(((t.y + dy + 32) % 32) * 32 + (t.x + dx + 32) % 32)] == n;
      if (!interior) continue;
      const NdfImage img = p.image(level.first_footprint + static_cast<std::uint32_t>(y * level.nx + x));
      glm::dvec2 sum(0.0);
      double mass = 0.0;
      for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
          sum += static_cast<double>(img.at(i, j)) * p.grid.pixel_centre(i, j);
          mass += img.at(i, j);
        }
      const glm::dvec2 centroid = sum / mass;
      EXPECT_NEAR(centroid.x, n.x, p.grid.pixel_size());
      EXPECT_NEAR(centroid.y, n.y, p.grid.pixel_size());
      ++checked;
    }
  EXPECT_GT(checked, 8);
}

TEST(PrefilteredNdf, UniformMapStopsAfterOneLevelAbove) {
  const NormalMap flat{16, 16, std::vector<glm::vec3>(256, glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f))), "uniform"};
  PrefilterSettings s = small_settings();
  s.base_stride = 1;
  const PrefilteredNdf p = precompute_prefiltered_ndf(flat, 0.02, s);
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_LT(p.levels[1].distance_to_level_below, 1e-3);
}

// Issue 30, item 7: a box query from its four corners through the prefix tables is the block by
// block sum (eq. 7) for boxes inside one block, across block rows and columns, and over the whole
// image, in every footprint of every level.
TEST(PrefilteredNdf, BoxQueriesFromTheirCornersEqualTheBlockByBlockSum) {
  const PrefilteredNdf& p = pyramid();
  const BoxPrefixTables tables = box_prefix_tables(p);
  ASSERT_EQ(tables.values.size(), p.footprints.size() * static_cast<std::size_t>(p.blocks_per_side() * p.blocks_per_side() *
                                                                                (2 * p.rank() + 1)));
  const double n = p.grid.resolution, b = p.settings.block_size;
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double peak = 0.0;
  for (std::uint32_t f = 0; f < p.footprints.size(); ++f)
    peak = std::max(peak, p.pixel_range_sum(f, {0, 0}, {n, n}));
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto f = static_cast<std::uint32_t>(u(rng) * static_cast<double>(p.footprints.size()));
    glm::dvec2 x0, x1;
    switch (i % 4) {
      case 0:  // inside one block
        x0 = glm::floor(glm::dvec2(u(rng), u(rng)) * (n / b)) * b + glm::dvec2(u(rng), u(rng)) * 0.5 * b;
        x1 = x0 + glm::dvec2(u(rng), u(rng)) * 0.5 * b;
        break;
      case 1:  // one block column, several rows
        x0 = {std::floor(u(rng) * (n / b)) * b + 0.3 * b, u(rng) * n * 0.3};
        x1 = {x0.x + 0.5 * b, x0.y + u(rng) * 0.7 * n};
        break;
      case 2:  // anywhere
        x0 = glm::dvec2(u(rng), u(rng)) * n;
        x1 = x0 + glm::dvec2(u(rng), u(rng)) * (n - x0);
        break;
      default:  // the whole image
        x0 = {0, 0};
        x1 = {n, n};
    }
    const double expected = p.pixel_range_sum(f, x0, x1), got = box_prefix_range_sum(p, tables, f, x0, x1);
    ASSERT_NEAR(got, expected, 1e-5 * peak + 1e-4 * expected) << "footprint " << f << " box " << i;
    checked += expected > 1e-3 * peak ? 1 : 0;
  }
  EXPECT_GT(checked, 1000);  // boxes with mass, not only empty space
}

// Issue 30, item 4: sigma_0 in texels, and so the element fallback's cost below it, is the same on
// any map; only the number of footprints grows (the paper's fixed stride, sec. 4.1).
TEST(PrefilteredNdf, TheFinestLevelsStrideIsFixedWhateverTheMapsSize) {
  PrefilterSettings s = small_settings();
  s.base_stride = 2;
  s.max_levels = 1;
  for (const int side : {16, 32, 48}) {
    const NormalMap flat{side, side, std::vector<glm::vec3>(static_cast<std::size_t>(side * side), glm::vec3(0, 0, 1)),
                         "uniform"};
    const PrefilteredNdf p = precompute_prefiltered_ndf(flat, 0.02, s);
    ASSERT_EQ(p.levels.size(), 1u);
    EXPECT_EQ(p.levels[0].sigma, 2.0) << side;
    EXPECT_EQ(p.levels[0].nx, side / 2) << side;
    EXPECT_EQ(p.levels[0].spacing, glm::dvec2(2.0)) << side;
  }
}

TEST(PrefilteredNdf, NoNanInARandomisedSweep) {
  const PrefilteredNdf& p = pyramid();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec2 centre(100 * u(rng), 100 * u(rng));
    const double sigma = std::pow(10.0, 3 * u(rng));
    const glm::dvec2 s(1.5 * u(rng), 1.5 * u(rng));
    const glm::dvec2 half(std::abs(0.5 * u(rng)), std::abs(0.5 * u(rng)));
    const double d = p.density(centre, sigma, s), r = p.range_mean(centre, sigma, s - half, s + half);
    ASSERT_TRUE(std::isfinite(d) && d >= 0.0) << d;
    ASSERT_TRUE(std::isfinite(r) && r >= 0.0) << r;
  }
  EXPECT_TRUE(std::isfinite(p.density({0, 0}, 0.0, {0, 0})));
}

TEST(PrefilteredNdf, CacheRoundTripsAndRebuildsADamagedEntry) {
  const test::ScratchDirectory dir;
  const PrefilterSettings s = small_settings();
  const PrefilteredNdf a = load_or_precompute_prefiltered_ndf(bumps(), 0.03, s, dir.path());
  const PrefilteredNdf b = load_or_precompute_prefiltered_ndf(bumps(), 0.03, s, dir.path());
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.angular, b.angular);
  ASSERT_EQ(a.footprints.size(), b.footprints.size());
  const auto file = dir.path() / "prefiltered-ndf" / prefiltered_ndf_key(bumps(), 0.03, s);
  ASSERT_TRUE(std::filesystem::exists(file));
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  const PrefilteredNdf c = load_or_precompute_prefiltered_ndf(bumps(), 0.03, s, dir.path());
  EXPECT_EQ(a.rows, c.rows);
  EXPECT_NE(prefiltered_ndf_key(bumps(), 0.03, s), prefiltered_ndf_key(bumps(), 0.031, s));
  // A grid chosen at precompute (a 0 asked for: here B = N / 4) comes back from the cache as chosen.
  PrefilterSettings chosen = s;
  chosen.block_size = 0;
  const PrefilteredNdf made = load_or_precompute_prefiltered_ndf(bumps(), 0.03, chosen, dir.path());
  const PrefilteredNdf read = load_or_precompute_prefiltered_ndf(bumps(), 0.03, chosen, dir.path());
  ASSERT_GT(made.settings.block_size, 0);
  EXPECT_EQ(read.settings.ndf_resolution, made.settings.ndf_resolution);
  EXPECT_EQ(read.settings.block_size, made.settings.block_size);
  EXPECT_EQ(read.blocks_per_side(), made.blocks_per_side());
}

/// Entries that a checksum cannot catch (a consistent frame around wrong bytes, as a bug or a
/// hostile writer makes them) and special files: each one is reported, and the pyramid is rebuilt
/// equal to the precompute's.
// The pyramid fuzzer's seeds (fuzz/corpus/pyramid/) are payloads of the current entry format: the
// seed of a real entry reads, and the two findings are refused by check_consistent (a seed of an
// old format would fail at its first bytes and fuzz nothing past them).
TEST(PrefilteredNdf, TheFuzzSeedsAreOfTheCurrentFormat) {
  const auto read = [](const char* name) {
    std::ifstream in(std::string(GLINTLAB_SOURCE_DIR "/fuzz/corpus/pyramid/") + name, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    std::istringstream payload(bytes.str());
    return PrefilteredNdf::read(payload);
  };
  const PrefilteredNdf seed = read("bumps-16-rank2.bin");
  EXPECT_EQ(seed.width, 16);
  EXPECT_EQ(seed.rank(), 2);
  EXPECT_FALSE(seed.partial);
  for (const char* finding : {"finding-tiny-spacing.bin", "finding-tiny-extent.bin"}) {
    try {
      (void)read(finding);
      ADD_FAILURE() << finding << " reads";
    } catch (const RuntimeFailure& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what.find("bad footprint grid") != std::string::npos || what.find("extent") != std::string::npos)
          << finding << ": " << what;
    }
  }
}

TEST(PrefilteredNdf, CacheRebuildsEveryInconsistentOrSpecialEntry) {
  const test::ScratchDirectory dir;
  const PrefilterSettings s = small_settings();
  const auto file = dir.path() / "prefiltered-ndf" / prefiltered_ndf_key(bumps(), 0.03, s);
  const std::string built_from = prefiltered_ndf_built_from(bumps(), 0.03, s);
  const PrefilteredNdf& good = pyramid();
  auto store = [&](const PrefilteredNdf& p) {
    std::ostringstream bytes;
    p.write(bytes);
    ASSERT_EQ(write_cache_entry(file, kPrefilteredNdfMagic, built_from, bytes.str()), "");
  };
  auto expect_rebuilt = [&](const char* case_name, const char* problem) {
    ::testing::internal::CaptureStderr();
    const PrefilteredNdf p = load_or_precompute_prefiltered_ndf(bumps(), 0.03, s, dir.path());
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("ignoring the cache entry"), std::string::npos) << case_name << ": " << err;
    EXPECT_NE(err.find(problem), std::string::npos) << case_name << ": " << err;
    EXPECT_EQ(p.rows, good.rows) << case_name;
    EXPECT_EQ(p.footprints.size(), good.footprints.size()) << case_name;
  };
  PrefilteredNdf bad = good;
  bad.levels[0].nx = 1 << 30;  // a huge footprint count on level 0
  store(bad);
  expect_rebuilt("huge level", "bad footprint grid");
  bad = good;
  bad.levels[0].first_footprint = 7;
  store(bad);
  expect_rebuilt("bad first footprint", "does not start where");
  bad = good;
  bad.levels[0].spacing.x = 1e-300;  // fuzz/fuzz_pyramid.cpp: a query's grid position overflowed int
  store(bad);
  expect_rebuilt("tiny spacing", "bad footprint grid");
  bad = good;
  bad.grid.extent = 1e-100;  // fuzz/fuzz_pyramid.cpp: a query's pixel position overflowed int
  store(bad);
  expect_rebuilt("tiny extent", "grid extent");
  bad = good;
  bad.levels[0].sigma = std::nan("");
  store(bad);
  expect_rebuilt("NaN sigma", "bad sigma");
  bad = good;
  std::fill(bad.group_offsets.begin(), bad.group_offsets.end(), 0u);  // every group reads the first's factors
  store(bad);
  expect_rebuilt("zeroed group offsets", "does not follow");
  bad = good;
  bad.rows[3] = std::nanf("");
  store(bad);
  expect_rebuilt("NaN value", "not finite");
  bad = good;
  bad.width = 64;
  store(bad);
  expect_rebuilt("other map size", "bad footprint grid");  // its footprints no longer tile it
  bad = good;
  bad.intrinsic_roughness = 0.031;  // consistent, but not the pyramid asked for
  store(bad);
  expect_rebuilt("other roughness", "intrinsic roughness differs");
  // An array size of 2^32 in a few bytes: refused before anything is allocated.
  std::ostringstream bytes;
  good.write(bytes);
  std::string huge = bytes.str();
  // PrefilteredNdf::write: four ints, the grid's extent, width and height, two doubles, the level
  // count, the levels, then the footprints' count.
  const std::size_t footprint_count_at = 6 * sizeof(int) + 3 * sizeof(double) + sizeof(std::uint64_t) +
                                         good.levels.size() * sizeof(PrefilterLevel);
  const std::uint64_t count = std::uint64_t{1} << 32;
  ASSERT_LT(footprint_count_at + 8, huge.size());
  std::memcpy(huge.data() + footprint_count_at, &count, sizeof count);
  ASSERT_EQ(write_cache_entry(file, kPrefilteredNdfMagic, built_from, huge), "");
  expect_rebuilt("huge array", "prefiltered NDF");
  // One byte flipped: the checksum.
  store(good);
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(std::filesystem::file_size(file) / 2));
    f.put('\x5a');
  }
  expect_rebuilt("flipped byte", "checksum");
  // A FIFO in the entry's place: neither opened (it would block) nor replaced.
  std::filesystem::remove(file);
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  expect_rebuilt("FIFO", "FIFO");
  EXPECT_TRUE(std::filesystem::is_fifo(file));
}

TEST(PrefilteredNdf, PackedLayoutPointsAtEachMaterialsPyramid) {
  const PrefilteredNdf& p = pyramid();
  const std::vector<const PrefilteredNdf*> materials = {nullptr, &p, nullptr, &p};
  const PrefilteredNdfBuffers packed = pack_prefiltered_ndfs(materials, 8);
  EXPECT_EQ(packed.records[0], kNoPrefilteredNdf);
  EXPECT_EQ(packed.records[2], kNoPrefilteredNdf);
  for (int m : {1, 3}) {
    const std::uint32_t h = packed.records[static_cast<std::size_t>(m)];
    EXPECT_EQ(packed.records[h], p.levels.size());
    EXPECT_EQ(packed.records[h + 3], static_cast<std::uint32_t>(p.rank()));
    const std::uint32_t rows = packed.records[h + 8];
    EXPECT_EQ(packed.values[rows], p.rows[0]);
  }
}

}  // namespace
}  // namespace glintlab
