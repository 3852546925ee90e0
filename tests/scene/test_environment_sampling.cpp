// Importance sampling the environment map (src/scene/lights/environment_sampling.hpp): the CDF
// texture's layout, a chi-square test of the CPU reference sampler against the texel
// probabilities f / sum f computed here, and the solid-angle pdf's normalisation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/lights/environment_map.hpp"
#include "scene/lights/environment_sampling.hpp"
#include "chi_square.hpp"

using namespace glintlab;
using glintlab::test::chi_square;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// 32 x 16: a dim gradient, a hot spot of 2 x 1 texels, and a black row (row 12).
Image hot_spot_map() {
  Image map(32, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) map.at(x, y) = glm::vec3(0.05f + 0.01f * x, 0.1f, 0.02f * y);
  map.at(20, 5) = glm::vec3(300.0f, 200.0f, 100.0f);
  map.at(21, 5) = glm::vec3(10.0f, 400.0f, 0.0f);
  for (int x = 0; x < 32; ++x) map.at(x, 12) = glm::vec3(0.0f);
  return map;
}

/// f(x, y) = luminance sin(theta_y), independently of the builder.
std::vector<double> texel_weights(const Image& map, bool with_sine = true) {
  std::vector<double> f;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const glm::vec3 c = map.at(x, y);
      const double lum = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
      f.push_back(lum * (with_sine ? std::sin(kPi * (y + 0.5) / map.height()) : 1.0));
    }
  return f;
}

}  // namespace

TEST(EnvironmentSampling, CdfRowsAreMonotoneFromZeroToOne) {
  const Image map = hot_spot_map();
  const EnvironmentSampling s = build_environment_sampling(map);
  ASSERT_EQ(s.width, 32);
  ASSERT_EQ(s.height, 16);
  ASSERT_EQ(s.cdf.size(), std::size_t{33} * 17);
  for (int y = 0; y < s.height; ++y) {
    EXPECT_EQ(s.conditional(y, 0), 0.0f);
    EXPECT_EQ(s.conditional(y, s.width), 1.0f);
    for (int i = 0; i < s.width; ++i) EXPECT_LE(s.conditional(y, i), s.conditional(y, i + 1)) << y << ", " << i;
  }
  for (int i = 0; i <= s.width; ++i) EXPECT_NEAR(s.conditional(12, i), i / 32.0, 1e-7) << "the black row is uniform";
  EXPECT_EQ(s.marginal(0), 0.0f);
  EXPECT_EQ(s.marginal(s.height), 1.0f);
  for (int y = 0; y < s.height; ++y) EXPECT_LE(s.marginal(y), s.marginal(y + 1));
  EXPECT_EQ(s.marginal(12), s.marginal(13)) << "the black row is never chosen";
  for (int i = s.height + 1; i <= s.width; ++i) EXPECT_EQ(s.marginal(i), 0.0f) << "padding";

  double sum = 0;
  for (double f : texel_weights(map)) sum += f;
  EXPECT_NEAR(s.integral, sum / (32.0 * 16.0), 1e-9 * sum);
}

TEST(EnvironmentSampling, ABlackMapHasNoIntegralAndUniformCdfs) {
  const EnvironmentSampling s = build_environment_sampling(Image(8, 4));
  EXPECT_EQ(s.integral, 0.0);
  for (int y = 0; y <= 4; ++y) EXPECT_NEAR(s.marginal(y), y / 4.0, 1e-7);
  EXPECT_EQ(environment_pdf(s, {0, 0, -1}), 0.0);
}

TEST(EnvironmentSampling, SamplesFollowTheTexelProbabilities) {
  const Image map = hot_spot_map();
  const EnvironmentSampling s = build_environment_sampling(map);
  const std::vector<double> f = texel_weights(map);
  double sum = 0;
  for (double v : f) sum += v;

  constexpr int kSamples = 1 << 20;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> observed(f.size(), 0.0), sub_texel(2, 0.0);
  double worst_pdf = 0;
  for (int i = 0; i < kSamples; ++i) {
    double pdf_uv = 0;
    const glm::dvec2 uv = sample_environment_uv(s, {unit(rng), unit(rng)}, &pdf_uv);
    ASSERT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
    const int x = std::min(static_cast<int>(uv.x * 32), 31), y = std::min(static_cast<int>(uv.y * 16), 15);
    observed[static_cast<std::size_t>(y) * 32 + x] += 1;
    // The uv density is f / I of the texel it landed in.
    const double expected_pdf = f[static_cast<std::size_t>(y) * 32 + x] / (sum / (32.0 * 16.0));
    worst_pdf = std::max(worst_pdf, std::abs(pdf_uv - expected_pdf) / expected_pdf);
    EXPECT_NEAR(environment_pdf_uv(s, uv), pdf_uv, 1e-9 * pdf_uv);
    if (x == 20 && y == 5) sub_texel[uv.x * 32 - 20 < 0.5 ? 0 : 1] += 1;
  }
  // The CDFs are floats: a texel's probability is a difference of two, exact to about 2^-24.
  EXPECT_LT(worst_pdf, 1e-3);
  EXPECT_EQ(observed[12 * 32 + 3], 0.0) << "a black row's texels are never sampled";

  std::vector<double> expected;
  for (double v : f) expected.push_back(kSamples * v / sum);
  const double p = chi_square(observed, expected).p;
  EXPECT_GT(p, 1e-3) << "samples against f / sum f";
  // The same histogram against luminance without sin(theta) is refused: the test can fail.
  std::vector<double> wrong;
  const std::vector<double> no_sine = texel_weights(map, false);
  double no_sine_sum = 0;
  for (double v : no_sine) no_sine_sum += v;
  for (double v : no_sine) wrong.push_back(kSamples * v / no_sine_sum);
  EXPECT_LT(chi_square(observed, wrong).p, 1e-6);
  // Within a texel the sample is uniform (linear placement): both halves of the hot texel alike.
  const double n = sub_texel[0] + sub_texel[1];
  EXPECT_NEAR(sub_texel[0] / n, 0.5, 4 * 0.5 / std::sqrt(n));
}

TEST(EnvironmentSampling, SolidAnglePdfIntegratesToOne) {
  const EnvironmentSampling s = build_environment_sampling(hot_spot_map());
  // Midpoints of a grid 4 times finer than the texels, in (theta, phi): d omega = sin dtheta dphi.
  constexpr int kRows = 64, kColumns = 128;
  double total = 0;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      const double u = (i + 0.5) / kColumns, v = (j + 0.5) / kRows;
      const glm::dvec3 d = environment_direction_precise(u, v);
      total += environment_pdf(s, d) * std::sin(kPi * v) * (kPi / kRows) * (2 * kPi / kColumns);
    }
  EXPECT_NEAR(total, 1.0, 1e-5);
}
