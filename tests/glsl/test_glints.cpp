// The glinty BRDF's GLSL (shaders/glints/chermain/dictionary.glsl, glints/chermain/ndf.glsl, glints/chermain/shading.glsl)
// on the GL device: the dictionary as the GPU reads it, filtered against unfiltered lookups,
// convergence of the patch-SDF to the (correlated) Beckmann distribution, and finiteness.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "brdf_sweep.hpp"
#include "gl_fixture.hpp"
#include "tables/glint_dictionary/glint_dictionary.hpp"
#include "tables/gpu_tables.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// The glint GLSL, and the roughness matrix A = 2 Sigma of slope deviations sigma and correlation rho.
const char* kIncludes = R"(#define MATERIAL_NORMAL_MAP 0
#include "glints/chermain/shading.glsl"
mat2 roughnessMatrix(vec2 sigma, float rho) {
  float c = rho * sigma.x * sigma.y;
  return 2.0 * mat2(sigma.x * sigma.x, c, c, sigma.y * sigma.y);
})";

/// The default dictionary bound where the shaders read it (TABLE_UNIT_GLINT_DICTIONARY).
void bind_dictionary() {
  static const GpuTables tables = [] {
    context();
    GpuTables t(test_table_cache());
    t.require(std::vector<std::string>{"glint-dictionary"});
    return t;
  }();
  tables.bind();
}

TEST(Glints, ShaderConstantsAreTheGeneratorsDefaults) {
  // The table declares them from its settings (the defaults, the paper's dictionary).
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(GLINT_MARGINALS, GLINT_LEVELS, GLINT_DICT_SIGMA, GLINT_SLOPE_RANGE); })",
                               {glm::vec4(0)}, {glm::vec4(0)});
  const GlintDictionarySettings st;
  EXPECT_EQ(r[0].x, static_cast<float>(st.marginals));
  EXPECT_EQ(r[0].y, static_cast<float>(st.levels));
  EXPECT_EQ(r[0].z, st.sigma());
  EXPECT_EQ(r[0].w, st.slope_range());
}

TEST(Glints, TextureLookupsIntegrateToOneUnfilteredAndFiltered) {
  // Every marginal at every level, read through the texture (layout, texel centres, mirrored
  // repeat, half floats), integrated over the whole line; filtered lookups (a kernel of 8 texels:
  // mip 3) keep the integral, which is why GGAA conserves energy (2021, sec. 4.2).
  bind_dictionary();
  const GlintDictionarySettings st;
  std::vector<glm::vec4> a, b;
  for (int level = 0; level < st.levels; ++level)
    for (int k = 0; k < st.marginals; ++k) {
      a.emplace_back(level, k, 0.0f, 0.0f);
      a.emplace_back(level, k, 8.0f * st.slope_range() / st.texels, 0.0f);
    }
  b.resize(a.size());
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  const int n = 2048;
  float ds = 2.0 * GLINT_SLOPE_RANGE / float(n), sum = 0.0;
  for (int i = 0; i < n; ++i) {
    float s = -GLINT_SLOPE_RANGE + (float(i) + 0.5) * ds;
    sum += glintMarginalFiltered(int(a.x), int(a.y), s, a.z, 0.0);
  }
  return vec4(sum * ds);
})",
                               a, b);
  double worst_unfiltered = 0, worst_filtered = 0;
  for (std::size_t i = 0; i < r.size(); i += 2) {
    worst_unfiltered = std::max(worst_unfiltered, std::abs(r[i].x - 1.0));
    worst_filtered = std::max(worst_filtered, std::abs(r[i + 1].x - 1.0));
  }
  EXPECT_LT(worst_unfiltered, 0.005);
  EXPECT_LT(worst_filtered, 0.005);
}

TEST(Glints, FilteredLookupsWithZeroDerivativesEqualUnfilteredOnes) {
  bind_dictionary();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> a;
  for (int i = 0; i < 4096; ++i)
    a.emplace_back(std::floor(16 * u(rng)), std::floor(192 * u(rng)), 2.8f * (u(rng) - 0.5f), 0.0f);
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  int l = int(a.x), k = int(a.y);
  return vec4(glintMarginal(l, k, a.z), glintMarginalFiltered(l, k, a.z, 0.0, 0.0),
              glintMarginalFiltered(l, k, a.z, 0.3, 0.0), 0.0);
})",
                               a, std::vector<glm::vec4>(a.size()));
  int blurred = 0;
  for (const auto& v : r) {
    ASSERT_EQ(v.x, v.y);
    blurred += v.z != v.x;
  }
  EXPECT_GT(blurred, 1000) << "a non-zero kernel must change the lookups (the test can fail)";
}

// The mean of the patch-SDF over many small footprints at random places, at slopes along a few
// directions, against the Beckmann density of the same covariance (2021, eqs. 16-18). The
// footprints are spread over invocations: llvmpipe stops a shader's loops after 65535 iterations
// in all (its loop limiter), which one invocation looping over thousands of footprints would hit.
void expect_converges_to_beckmann(glm::vec2 sigma, float rho) {
  bind_dictionary();
  constexpr int kChunks = 64;  // invocations per slope, 64 footprints each
  std::vector<glm::vec4> a, b;
  std::vector<glm::vec2> slopes;
  for (float t : {0.0f, 0.5f, 1.0f})
    for (float angle : {0.0f, 0.785f, 1.571f, 2.356f}) {
      slopes.push_back(t * sigma * glm::vec2(std::cos(angle), std::sin(angle)));
      for (int c = 0; c < kChunks; ++c) {
        a.emplace_back(slopes.back(), sigma);
        b.emplace_back(rho, c, 0, 0);
      }
    }
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  GlintLobe lobe = glintLobe(roughnessMatrix(a.zw, b.x));
  // Footprints of 2^-10 uv (level 5); ln(density) such that cells use dictionary levels near 10.
  GlintQuery q = GlintQuery(a.xy, vec2(0.0), vec2(0.0), false, 27.7, 1.0);
  float sum = 0.0;
  for (int i = 0; i < 64; ++i) {
    float k = float(i + 64 * int(b.y));
    vec2 uv = vec2(fract(k * 0.7548777), fract(k * 0.5698403)) * 3.0;
    GlintPatch fp = glintPatch(uv, uvFootprint(vec2(exp2(-10.0), 0.0), vec2(0.0, exp2(-10.0))), 8.0);
    sum += glintP22(q, lobe, fp);
  }
  return vec4(sum / 64.0, slopeDensityBeckmann(a.xy, lobe.A), 0.0, 0.0);
})",
                               a, b);
  for (std::size_t s = 0; s < slopes.size(); ++s) {
    double mean = 0.0;
    for (int c = 0; c < kChunks; ++c) mean += r[s * kChunks + static_cast<std::size_t>(c)].x / kChunks;
    const double expected = r[s * kChunks].y;
    EXPECT_NEAR(mean, expected, 0.03 * expected) << "slope " << slopes[s].x << ", " << slopes[s].y << " rho " << rho;
  }
}

TEST(Glints, PatchDistributionConvergesToBeckmann) { expect_converges_to_beckmann({0.1f, 0.1f}, 0.0f); }
TEST(Glints, PatchDistributionConvergesToRotatedAnisotropicBeckmannWithRho) {
  expect_converges_to_beckmann({0.15f, 0.06f}, 0.6f);
}

TEST(Glints, BrdfIsFiniteAndNonNegativeInARandomizedSweep) {
  bind_dictionary();
  const BrdfSweepInputs in = brdf_sweep_inputs(17, 1 << 14, 2.0f);
  const auto r = evaluate_glsl(kIncludes, R"(
float rand(float i, float k) { return fract(sin(i * 12.9898 + k * 78.233) * 43758.5453); }
vec4 evaluate(vec4 a, vec4 b) {
  float i = b.w;
  float scale = a.w;
  vec2 uv = (vec2(rand(i, 1.0), rand(i, 2.0)) - 0.5) * 2000.0;
  vec2 d0 = scale * vec2(rand(i, 3.0) - 0.5, rand(i, 4.0) - 0.5);
  vec2 d1 = scale * pow(10.0, -3.0 * rand(i, 5.0)) * vec2(rand(i, 6.0) - 0.5, rand(i, 7.0) - 0.5);
  GlintPatch fp = glintPatch(uv, uvFootprint(d0, d1), 1.0 + 63.0 * rand(i, 8.0));
  vec2 sigma = vec2(0.005) + 0.995 * vec2(rand(i, 9.0), rand(i, 10.0));
  float rho = 1.98 * rand(i, 11.0) - 0.99;
  GlintSurface g = GlintSurface(fp, glintLobe(roughnessMatrix(sigma, rho)), 60.0 * rand(i, 12.0), rand(i, 13.0));
  vec2 kx = pow(10.0, 6.0 * rand(i, 14.0) - 6.0) * vec2(rand(i, 15.0) - 0.5, rand(i, 16.0));
  vec2 ky = rand(i, 17.0) < 0.2 ? vec2(0.0) : kx.yx;
  vec3 f0 = vec3(rand(i, 18.0));
  vec3 plain = glintSpecularCos(g, a.xyz, b.xyz, f0, vec2(0.0), vec2(0.0), false);
  vec3 filtered = glintSpecularCos(g, a.xyz, b.xyz, f0, kx, ky, true);
  bool below = a.z <= 0.0 || b.z <= 0.0;
  return vec4(plain.x, filtered.x, below ? max(plain.x, filtered.x) : 0.0, 0.0);
})",
                               in.a, in.b);
  int lit = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    ASSERT_TRUE(std::isfinite(r[i].x) && std::isfinite(r[i].y)) << "case " << i;
    ASSERT_GE(r[i].x, 0.0f) << "case " << i;
    ASSERT_GE(r[i].y, 0.0f) << "case " << i;
    ASSERT_EQ(r[i].z, 0.0f) << "case " << i << ": light or view below the surface";
    lit += r[i].x > 0.0f;
  }
  EXPECT_GT(lit, 100) << "the sweep must reach lit configurations";
}

}  // namespace
