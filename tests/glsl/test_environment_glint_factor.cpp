// kneiphof2025's glint factor g (shaders/glints/binomial/environment_glints.glsl) on the GL device:
// over many footprints its mean is 1 (the glints' mean is the split sum's), at densities from a
// few facets a footprint to many, for regions of very different luminance and share.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(const int LIGHT_CELLS = 4;
#include "glints/binomial/environment_glints.glsl"
)";

struct Case {
  double log_density;
  glm::vec3 weights, levels;
  float p;
};

TEST(EnvironmentGlintFactor, ItsMeanOverFootprintsIsOne) {
  const std::vector<Case> cases = {
      // Footprints of 2^-18 to 2^-16 uv units: ln density 14 holds about 1 to 5 facets, 18 about 70 to
      // 280, 22 thousands.
      {14.0, {0.3f, 0.2f, 0.05f}, {1.0f, 10.0f, 100.0f}, 0.6f},
      {18.0, {0.3f, 0.2f, 0.05f}, {1.0f, 10.0f, 100.0f}, 0.6f},
      {22.0, {0.5f, 0.1f, 0.002f}, {0.5f, 30.0f, 2000.0f}, 0.9f},
      {18.0, {0.0f, 0.0f, 0.01f}, {1.0f, 2.0f, 4.0f}, 0.3f},
  };
  for (const Case& c : cases) {
    constexpr int kFootprints = 8192;
    std::vector<glm::vec4> a, b;
    for (int i = 0; i < kFootprints; ++i) {
      a.emplace_back(static_cast<float>(c.log_density), static_cast<float>(i), c.p, 0.0f);
      b.emplace_back(c.weights, 0.0f);
    }
    char levels[96];
    std::snprintf(levels, sizeof levels, "vec3(%.9g, %.9g, %.9g)", c.levels.x, c.levels.y, c.levels.z);
    const auto r = evaluate_glsl(kIncludes, std::string(R"(
vec4 evaluate(vec4 a, vec4 b) {
  float k = a.y;
  vec2 uv = vec2(fract(k * 0.7548777), fract(k * 0.5698403)) * 50.0;
  float angle = 6.2831853 * fract(k * 0.618034);
  vec2 dx = exp2(-9.0) * vec2(cos(angle), sin(angle));
  vec2 dy = exp2(-9.0) * (1.0 + 3.0 * fract(k * 0.41421356)) * vec2(-sin(angle), cos(angle));
  BinomialSurface s = binomialSurface(uv, binomialFootprint(uvFootprint(dx, dy), 1.5), a.x, 0.5, 0.02, 16.0);
  return vec4(environmentGlintFactorOfWeights(s, b.xyz, )") + levels + R"(, a.z, REMAINING_COUNT_LOGNORMAL));
})",
                                 a, b);
    double sum = 0, sum2 = 0;
    for (const auto& v : r) {
      ASSERT_TRUE(std::isfinite(v.x));
      ASSERT_GE(v.x, 0.0f);
      sum += v.x;
      sum2 += double(v.x) * v.x;
    }
    const double mean = sum / kFootprints, error = std::sqrt((sum2 / kFootprints - mean * mean) / kFootprints);
    EXPECT_NEAR(mean, 1.0, 4.0 * error + 0.01)
        << "ln density " << c.log_density << ", weights " << c.weights.x << " " << c.weights.y << " " << c.weights.z
        << ": mean " << mean << " +- " << error;
  }
}

}  // namespace
