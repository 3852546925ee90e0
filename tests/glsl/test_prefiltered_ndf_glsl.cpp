// deng2022's GLSL queries (shaders/glints/normal-map/prefiltered_ndf.glsl) against the C++ ones
// (src/prefilter/prefiltered_ndf.cpp) on the same packed pyramid: point and box queries (block by
// block and through the box prefix tables) over random footprints (inside and outside the pyramid's
// range of sigma) and half vectors, with N, B and R read from the header or compiled in.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <tuple>

#include "chi_square.hpp"
#include "core/gpu_contract.hpp"
#include "gl_fixture.hpp"
#include "ndf_histogram.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "prefilter/ndf_sampling.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"

using namespace glintlab;
using namespace glintlab::test;
using glintlab::test::chi_square;

namespace {

// A small pyramid (a 32^2 bumps map, sigma_r 0.03, 32^2 NDF pixels in 8^2 blocks) bound as material
// 2's (materials 0 and 1 have none), as the renderer packs a scene's.
struct BoundPyramid {
  static constexpr double kSigmaR = 0.03;
  PrefilterSettings settings;
  NormalMap map = generate_bumps(32, 0.3f, 48, 6, 21);
  PrefilteredNdf pyramid;
  gl::Buffer records, values;

  explicit BoundPyramid(bool box_prefix_tables = true) {
    shaders();  // a current GL context before the buffers below
    settings.ndf_resolution = 32;
    settings.block_size = 8;
    settings.base_stride = 1;
    pyramid = precompute_prefiltered_ndf(map, kSigmaR, settings);
    const std::vector<const PrefilteredNdf*> materials = {nullptr, nullptr, &pyramid};
    const PrefilteredNdfBuffers packed = pack_prefiltered_ndfs(materials, kMaxMaterials, box_prefix_tables);
    records = gl::make_buffer(static_cast<GLsizeiptr>(packed.records.size() * 4), packed.records.data());
    values = gl::make_buffer(static_cast<GLsizeiptr>(packed.values.size() * 4), packed.values.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfRecordsBinding, records.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfValuesBinding, values.id());
  }
};

}  // namespace

TEST(PrefilteredNdfGlsl, QueriesAgreeWithTheCpu) {
  const BoundPyramid bound;
  const PrefilteredNdf& p = bound.pyramid;

  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 600; ++i) {
    const float sigma = std::pow(2.0f, 8.0f * u(rng) - 2.0f);  // 0.25 .. 64 texels: below, across and above the levels
    a.emplace_back(64.0f * u(rng) - 16.0f, 64.0f * u(rng) - 16.0f, sigma, 2.0f);
    const float e = static_cast<float>(p.grid.extent);
    b.emplace_back((2 * u(rng) - 1) * 1.1f * e, (2 * u(rng) - 1) * 1.1f * e, 0.3f * e * u(rng) * u(rng), 0.3f * e * u(rng));
  }
  // With N, B and R read from the header, and compiled in as deng2022 does (PNDF_COMPILED_SHAPE).
  const std::string compiled = "#define PNDF_COMPILED_SHAPE\nconst int PNDF_FIXED_N = " +
                               std::to_string(p.grid.resolution) + ", PNDF_FIXED_B = " +
                               std::to_string(p.settings.block_size) + ", PNDF_FIXED_RANK = " +
                               std::to_string(p.rank()) + ";\n";
  for (const std::string& shape : {std::string(), compiled}) {
    const auto out = evaluate_glsl(shape + "#include \"glints/normal-map/prefiltered_ndf.glsl\"", R"(
vec4 evaluate(vec4 a, vec4 b) {
  int m = int(a.w);
  if (!pndfPresent(m) || pndfPresent(0)) return vec4(-1.0);
  PndfHeader h = pndfHeader(m);
  return vec4(pndfDensity(h, a.xy, a.z, b.xy), pndfRangeMean(h, a.xy, a.z, b.xy - b.zw, b.xy + b.zw, false),
              pndfRangeMean(h, a.xy, a.z, b.xy - b.zw, b.xy + b.zw, true), 0.0);
})",
                                   a, b);
    int nonzero = 0;
    const char* which = shape.empty() ? "shape from the header" : "shape compiled in";
    for (std::size_t i = 0; i < a.size(); ++i) {
      const glm::dvec2 centre(a[i].x, a[i].y), s(b[i].x, b[i].y), half(b[i].z, b[i].w);
      const double d = p.density(centre, a[i].z, s), r = p.range_mean(centre, a[i].z, s - half, s + half);
      ASSERT_NE(out[i].x, -1.0f) << "the packed pyramid's material offsets";
      EXPECT_NEAR(out[i].x, d, 2e-4 * d + 1e-4) << "point query " << i << ", " << which;
      // The box query subtracts prefix sums: in float on the device, in double here.
      EXPECT_NEAR(out[i].y, r, 2e-3 * r + 1e-4) << "box query, block by block " << i << ", " << which;
      // From the corners: differences of float prefix sums of the whole image.
      EXPECT_NEAR(out[i].z, r, 2e-3 * r + 1e-3) << "box query, prefix tables " << i << ", " << which;
      nonzero += d > 0.1 ? 1 : 0;
    }
    EXPECT_GT(nonzero, 50);  // the sweep reaches the NDF's mass, not just empty space
  }
}

// deng2022's reading of an anisotropic footprint (shaders/glints/normal-map/footprint_probes.glsl):
// isotropic pyramid queries along its major axis against the exact P-NDF of the footprint in its
// true shape (the CPU's sum over the same elements, src/prefilter/position_normal.hpp). One query
// of the same area (anisotropic_probes = 1) blurs across the footprint and cuts it along; the
// probes keep both (measured: 0.149 relative L2 against 0.251).
TEST(PrefilteredNdfGlsl, ProbesAlongTheMajorAxisApproachTheExactNdfOfAnAnisotropicFootprint) {
  const BoundPyramid bound;
  const PrefilteredNdf& p = bound.pyramid;
  const PositionNormalDistribution exact(bound.map, BoundPyramid::kSigmaR, bound.settings.elements_per_texel);

  std::mt19937 rng(30);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e = p.grid.extent;
  std::vector<Footprint> footprints;
  std::vector<glm::vec4> a, b;
  for (int f = 0; f < 24; ++f) {
    const double minor = 1.5 + 1.5 * u(rng), ratio = 4.0 + 4.0 * u(rng), angle = 6.2831853 * u(rng);
    const glm::dvec2 axis(std::cos(angle), std::sin(angle)), across(-axis.y, axis.x);
    const glm::dmat2 cov = minor * minor * (glm::outerProduct(across, across) + ratio * ratio * glm::outerProduct(axis, axis));
    footprints.push_back({{32.0 * u(rng), 32.0 * u(rng)}, cov});
    for (int i = 0; i < 64; ++i) {
      a.emplace_back(cov[0][0], cov[0][1], cov[1][1], 0.0f);
      b.emplace_back(e * (1.2 * u(rng) - 0.6), e * (1.2 * u(rng) - 0.6), footprints.back().centre);
    }
  }
  auto queries = [&](int probes) {
    for (glm::vec4& q : a) q.w = static_cast<float>(probes);
    return evaluate_glsl("#include \"glints/normal-map/prefiltered_ndf.glsl\"\n"
                         "#include \"glints/normal-map/footprint_probes.glsl\"\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  FootprintProbes p = footprintProbes(b.zw, mat2(a.x, a.y, a.y, a.z), pndfFirstSigma(pndfHeader(2)), int(a.w));
  float sum = 0.0;
  ProbeWeights w = p.weights;
  for (int j = 0; j < p.count; ++j) sum += nextProbeWeight(w) * pndfDensity(pndfHeader(2), probeCentre(p, j), p.sigma, b.xy);
  return vec4(sum, 0.0, 0.0, 0.0);
})", a, b);
  };
  const auto probed = queries(8), one = queries(1);
  double truth2 = 0, probed2 = 0, one2 = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double t = exact.density(footprints[i / 64], {b[i].x, b[i].y});
    truth2 += t * t;
    probed2 += (probed[i].x - t) * (probed[i].x - t);
    one2 += (one[i].x - t) * (one[i].x - t);
  }
  const double probed_error = std::sqrt(probed2 / truth2), one_error = std::sqrt(one2 / truth2);
  std::printf("anisotropic footprints: relative L2 to the exact P-NDF: probes %.4f, one query %.4f\n", probed_error,
              one_error);
  EXPECT_LT(probed_error, 0.7 * one_error);  // measured: 0.149 against 0.251
}

// The GLSL sampler of the pyramid (glints/normal-map/ndf_sampling.glsl, sec. 5.2) on the device,
// as the CPU's (tests/prefilter/test_ndf_sampling.cpp): its pdf is the C++ density over the C++
// mass, and a chi-square test of 20000 samples against that density over the cells between pixel
// centres (where the density is bilinear: its value at a cell's centre times the cell's area is
// the cell's integral) passes, while the density of a footprint twice as wide is told apart. Both
// packings: with the box prefix tables (a footprint between levels, 8 blended) and without (block
// by block; a stored level's footprint).
TEST(PrefilteredNdfGlsl, SamplesFollowTheDensityTheMethodEvaluates) {
  constexpr int kSamples = 20000;
  std::mt19937 rng(41);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (const auto& [tables, centre, sigma] : {std::tuple{true, glm::vec2(11.3f, 20.6f), 1.7f}, {false, glm::vec2(4.5f, 4.5f), 2.0f}}) {
    const BoundPyramid bound(tables);
    const PrefilteredNdf& p = bound.pyramid;
    std::vector<glm::vec4> a, b;
    for (int i = 0; i < kSamples; ++i) {
      a.emplace_back(centre, sigma, 2.0f);
      b.emplace_back(static_cast<float>(i), u(rng), u(rng), 0.0f);
    }
    const auto out = evaluate_glsl("#include \"glints/normal-map/ndf_sampling.glsl\"", R"(
vec4 evaluate(vec4 a, vec4 b) {
  NdfSample x = pndfSample(pndfHeader(int(a.w)), a.xy, a.z, uint(b.x), b.yz);
  return vec4(x.s, x.pdf, pndfSamplePdf(pndfHeader(int(a.w)), a.xy, a.z, x.s));
})",
                                   a, b);
    const auto cpu_pdf = [&](double s_sigma, glm::dvec2 s) { return prefiltered_ndf_pdf(p, glm::dvec2(centre), s_sigma, s); };
    std::vector<glm::dvec2> samples;
    for (const glm::vec4& x : out) {
      ASSERT_GT(x.z, 0.0f) << "a sample";
      const glm::dvec2 s(x.x, x.y);
      ASSERT_NEAR(x.z, x.w, 1e-5 * x.w) << "the sample's pdf is pndfSamplePdf's";
      ASSERT_NEAR(x.z, cpu_pdf(sigma, s), 2e-3 * x.z + 1e-4) << "the C++ density over the C++ mass";
      samples.push_back(s);
    }
    const auto [observed, outside] = ndf_histogram(samples, p.grid);
    const std::vector<double> expected = ndf_expected_counts(p.grid, samples.size(), [&](glm::dvec2 s) { return cpu_pdf(sigma, s); });
    const std::vector<double> wrong = ndf_expected_counts(p.grid, samples.size(), [&](glm::dvec2 s) { return cpu_pdf(2.0 * sigma, s); });
    const auto chi = chi_square(observed, expected);
    std::printf("GLSL deng2022 sampler at sigma %.2f (%s): %s\n", sigma, tables ? "prefix tables" : "block by block",
                (std::ostringstream() << chi).str().c_str());
    EXPECT_EQ(outside, 0);
    EXPECT_TRUE(chi.passes(2)) << chi;
    EXPECT_LT(chi_square(observed, wrong).p, 1e-6);
  }
}
