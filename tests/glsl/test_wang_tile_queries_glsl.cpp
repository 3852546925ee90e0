// deng2022's queries on a surface of Wang tiles in GLSL (shaders/glints/normal-map/wang_tile_queries.glsl)
// against the C++ twin (src/prefilter/wang_tile_pyramids.hpp) on the same 16 packed tile pyramids:
// point, box and mass queries over footprints that reach several cells, within the stored levels
// and past them; and sampling across tiles (a cell by its mass, then its tile's sampler) by
// chi-square against the density the queries evaluate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "chi_square.hpp"
#include "core/gpu_contract.hpp"
#include "gl_fixture.hpp"
#include "ndf_histogram.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"
#include "prefilter/wang_tile_pyramids.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kSigmaR = 0.03;
constexpr int kTileSize = 8, kTiles = 4, kSeed = 3;

// The 16 tile pyramids of a 32^2 bumps map's Wang tiles (8^2, a 32^2 surface) bound as material
// 1's (material 0 has none), as the renderer packs a scene's.
struct BoundTiles {
  NormalMap map = make_wang_tiled_map(generate_bumps(32, 0.25f, 48, 6, 9), {.tile_size = kTileSize, .tiles = kTiles, .seed = kSeed});
  std::vector<PrefilteredNdf> tiles;
  gl::Buffer records, values;

  BoundTiles() {
    shaders();  // a current GL context before the buffers below
    PrefilterSettings settings;
    settings.ndf_resolution = 32;
    settings.block_size = 8;
    settings.base_stride = 1;
    for (int t = 0; t < 16; ++t) tiles.push_back(precompute_wang_tile_pyramid(map, t, kSigmaR, settings));
    std::vector<std::vector<const PrefilteredNdf*>> materials(2);
    for (const PrefilteredNdf& p : tiles) materials[1].push_back(&p);
    const PrefilteredNdfBuffers packed =
        pack_prefiltered_ndfs(std::span<const std::vector<const PrefilteredNdf*>>(materials), kMaxMaterials, true);
    records = gl::make_buffer(static_cast<GLsizeiptr>(packed.records.size() * 4), packed.records.data());
    values = gl::make_buffer(static_cast<GLsizeiptr>(packed.values.size() * 4), packed.values.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfRecordsBinding, records.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfValuesBinding, values.id());
  }

  /// The C++ box mean and mass of the footprint (the sum over the reached cells' tiles).
  [[nodiscard]] double range_mean(glm::dvec2 centre, double sigma, glm::dvec2 lo, glm::dvec2 hi) const {
    double sum = 0.0;
    for_each_reached_tile(map, centre, sigma, 2, [&](std::array<std::int64_t, 2>, int tile, glm::dvec2 local) {
      sum += tiles[static_cast<std::size_t>(tile)].range_mean(local, sigma, lo, hi);
    });
    return sum;
  }
  [[nodiscard]] double mass(glm::dvec2 centre, double sigma) const {
    const double e = tiles.front().grid.extent;
    return range_mean(centre, sigma, glm::dvec2(-e), glm::dvec2(e)) * 4.0 * e * e;
  }
};

const std::string kPyramids = "WangPyramids w = wangPyramids(1, " + std::to_string(kTileSize) + ", " + std::to_string(kTiles) +
                              ", " + std::to_string(kSeed) + "u);\n";

}  // namespace

TEST(WangTileQueriesGlsl, AgreeWithTheCpu) {
  const BoundTiles bound;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  const float e = static_cast<float>(bound.tiles.front().grid.extent);
  for (int i = 0; i < 300; ++i) {
    // 0.5 .. 7 texels: every reached cell queried (stride 1); past the last level (8) from 6 on.
    const float sigma = 0.5f * std::pow(14.0f, u(rng));
    a.emplace_back(64.0f * u(rng) - 16.0f, 64.0f * u(rng) - 16.0f, sigma, 0.0f);
    b.emplace_back((2 * u(rng) - 1) * 0.8f * e, (2 * u(rng) - 1) * 0.8f * e, 0.3f * e * u(rng) * u(rng), 0.3f * e * u(rng));
  }
  const auto out = evaluate_glsl("#include \"glints/normal-map/wang_tile_queries.glsl\"", R"(
vec4 evaluate(vec4 a, vec4 b) {
  )" + kPyramids + R"(
  return vec4(wangDensity(w, a.xy, a.z, b.xy), wangRangeMean(w, a.xy, a.z, b.xy - b.zw, b.xy + b.zw, true),
              wangMass(w, a.xy, a.z), float(wangCells(w, a.xy, a.z).stride));
})",
                                 a, b);
  int nonzero = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec2 centre(a[i].x, a[i].y), s(b[i].x, b[i].y), half(b[i].z, b[i].w);
    ASSERT_EQ(out[i].w, 1.0f) << "every cell";
    const double d = wang_tiles_density(bound.map, bound.tiles, centre, a[i].z, s);
    const double r = bound.range_mean(centre, a[i].z, s - half, s + half), m = bound.mass(centre, a[i].z);
    EXPECT_NEAR(out[i].x, d, 2e-4 * d + 2e-4) << "point query " << i << " sigma " << a[i].z;
    EXPECT_NEAR(out[i].y, r, 2e-3 * r + 2e-3) << "box query " << i;
    EXPECT_NEAR(out[i].z, m, 2e-3) << "mass " << i;
    EXPECT_NEAR(m, 1.0, 0.03) << "a footprint's mass, whatever cells it reaches";
    nonzero += d > 0.1 ? 1 : 0;
  }
  EXPECT_GT(nonzero, 30);
}

TEST(WangTileQueriesGlsl, SamplingAcrossTilesFollowsTheDensity) {
  constexpr int kSamples = 12000;
  const BoundTiles bound;
  const PrefilteredNdf& any = bound.tiles.front();
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // At a lattice corner (four cells, four tiles), and past the last level (8) over 7 x 7 cells, all
  // of them queried (the stratified subset past 64 cells is the shader's own: the C++ twin sums all).
  for (const auto& [centre, sigma] : {std::pair{glm::vec2(16.2f, 7.9f), 2.5f}, {glm::vec2(3.0f, 29.0f), 8.5f}}) {
    std::vector<glm::vec4> a, b;
    for (int i = 0; i < kSamples; ++i) {
      a.emplace_back(centre, sigma, 0.0f);
      b.emplace_back(static_cast<float>(i), u(rng), u(rng), 0.0f);
    }
    const auto out = evaluate_glsl("#include \"glints/normal-map/wang_tile_queries.glsl\"", R"(
vec4 evaluate(vec4 a, vec4 b) {
  )" + kPyramids + R"(
  NdfSample x = wangSample(w, a.xy, a.z, uint(b.x), b.yz);
  WangCells c = wangCells(w, a.xy, a.z);
  return vec4(x.s, x.pdf, c.stride == 1 ? float(c.count.x * c.count.y) : -1.0);
})",
                                   a, b);
    const double mass = bound.mass(glm::dvec2(centre), sigma);
    const auto pdf = [&](double s_sigma, glm::dvec2 s) {
      return wang_tiles_density(bound.map, bound.tiles, glm::dvec2(centre), s_sigma, s) / mass;
    };
    std::vector<glm::dvec2> samples;
    for (const glm::vec4& x : out) {
      ASSERT_GT(x.z, 0.0f) << "a sample";
      ASSERT_NEAR(x.z, pdf(sigma, glm::dvec2(x.x, x.y)), 3e-3 * x.z + 1e-3) << "the C++ density over the C++ mass";
      samples.emplace_back(x.x, x.y);
    }
    const auto [observed, outside] = ndf_histogram(samples, any.grid);
    const std::vector<double> expected = ndf_expected_counts(any.grid, samples.size(), [&](glm::dvec2 s) { return pdf(sigma, s); });
    const std::vector<double> wrong = ndf_expected_counts(any.grid, samples.size(), [&](glm::dvec2 s) { return pdf(0.5 * sigma, s); });
    const auto chi = chi_square(observed, expected);
    std::printf("GLSL Wang-tile sampler at sigma %.1f over %g cells: %s\n", sigma, out.front().w,
                (std::ostringstream() << chi).str().c_str());
    EXPECT_GE(out.front().w, 4.0f);
    EXPECT_EQ(outside, 0);
    EXPECT_TRUE(chi.passes(2)) << chi;
    EXPECT_LT(chi_square(observed, wrong).p, 1e-6);
  }
}
