#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/metrics.hpp"
#include "core/student_t.hpp"

using namespace glintlab;

TEST(Metrics, RmseOfKnownImages) {
  Image a(2, 2, glm::vec3(1.0f)), b(2, 2, glm::vec3(1.0f));
  EXPECT_DOUBLE_EQ(rmse(a, b), 0.0);
  b.at(0, 0) = glm::vec3(3.0f);  // one pixel off by 2 in all channels: sqrt(3*4 / 12) = 1
  EXPECT_NEAR(rmse(a, b), 1.0, 1e-12);
  EXPECT_NEAR(max_abs_error(a, b), 2.0, 1e-12);
  EXPECT_NEAR(psnr(0.1), 20.0, 1e-9);
  EXPECT_TRUE(std::isinf(psnr(0.0)));
}

TEST(Metrics, EnergyRatioSeesLostHighlights) {
  Image ref(4, 1, glm::vec3(0.0f)), test(4, 1, glm::vec3(0.0f));
  ref.at(1, 0) = glm::vec3(4.0f);
  test.at(2, 0) = glm::vec3(2.0f);  // highlight moved and halved
  EXPECT_NEAR(energy_ratio(test, ref), 0.5, 1e-6);
  EXPECT_DOUBLE_EQ(energy_ratio(test, test), 1.0);
}

TEST(Metrics, SizeMismatchIsAnError) {
  EXPECT_THROW(rmse(Image(2, 2), Image(2, 3)), std::invalid_argument);
}

TEST(Metrics, FlickerIsZeroForAConstantErrorAndMeasuresAChangingOne) {
  FlickerAccumulator constant, changing;
  for (int t = 0; t < 5; ++t) {
    Image ref(3, 3, glm::vec3(static_cast<float>(t)));        // the scene changes...
    Image biased(3, 3, glm::vec3(static_cast<float>(t) + 0.5f));  // ...a constant bias follows it
    constant.add_frame(biased, ref);
    Image flickering(3, 3, glm::vec3(static_cast<float>(t) + (t % 2 ? 1.0f : 0.0f)));
    changing.add_frame(flickering, ref);
  }
  EXPECT_NEAR(constant.flicker(), 0.0, 1e-9);
  EXPECT_NEAR(changing.flicker(), 1.0, 1e-9);  // the error alternates 0, 1, 0, 1
}

TEST(Image, NonFiniteCount) {
  Image img(3, 1);
  img.at(0, 0).r = std::nanf("");
  img.at(2, 0).b = INFINITY;
  EXPECT_EQ(img.count_non_finite(), 2u);
}

// Student's t against its tabulated quantiles (e.g. Abramowitz & Stegun, table 26.10) and the
// normal limit.
TEST(StudentT, QuantilesMatchTheTables) {
  EXPECT_NEAR(glintlab::student_t_quantile(0.975, 1), 12.7062, 1e-3);
  EXPECT_NEAR(glintlab::student_t_quantile(0.975, 3), 3.18245, 1e-4);
  EXPECT_NEAR(glintlab::student_t_quantile(0.975, 15), 2.13145, 1e-4);
  EXPECT_NEAR(glintlab::student_t_quantile(0.95, 10), 1.81246, 1e-4);
  EXPECT_NEAR(glintlab::student_t_quantile(0.975, 1000000), 1.95996, 1e-4);
  EXPECT_NEAR(glintlab::student_t_quantile(0.025, 3), -3.18245, 1e-4);
  EXPECT_NEAR(glintlab::student_t_cdf(0.0, 5), 0.5, 1e-12);
  EXPECT_NEAR(glintlab::student_t_cdf(1.0, 1), 0.75, 1e-9);  // Cauchy: 1/2 + atan(1)/pi
}

// Against an independent realisation of glints: two images of the same sparse bright dots at
// different places have a large per-pixel RMSE and none in their tile means, and the same glint
// detail; a smooth image (flat or a ramp) has the means but no detail, and a sparser, brighter set
// of dots more of it. The per-pixel RMSE ranks the blur first, which is why these exist.
TEST(Metrics, BlockStatisticsJudgeGlintsAgainstAnIndependentRealisation) {
  const int size = 32, block = 8;
  auto dots = [&](int phase, int spacing, float value) {
    Image img(size, size, glm::vec3(0.0f));
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        if ((x + phase) % spacing == 0 && (y + 2 * phase) % spacing == 0) img.at(x, y) = glm::vec3(value);
    return img;
  };
  const Image reference = dots(2, 4, 16.0f);  // 4 dots a tile, mean 1
  const Image other = dots(1, 4, 16.0f);      // the same law, other places
  const Image flat(size, size, glm::vec3(1.0f));
  Image ramp(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) ramp.at(x, y) = glm::vec3(0.5f + x / 32.0f);
  const Image sparse = dots(2, 8, 64.0f);  // 1 dot a tile, mean 1
  EXPECT_GT(rmse(other, reference), 5.0);
  EXPECT_NEAR(block_rmse(other, reference, block), 0.0, 1e-9);
  const double detail = glint_detail(reference);
  EXPECT_NEAR(glint_detail(other) / detail, 1.0, 0.02);  // the border cuts the dots a little differently
  EXPECT_LT(rmse(flat, reference), rmse(other, reference));  // the per-pixel RMSE prefers the blur
  EXPECT_NEAR(block_rmse(flat, reference, block), 0.0, 1e-6);
  EXPECT_NEAR(glint_detail(flat), 0.0, 1e-9);
  EXPECT_NEAR(glint_detail(ramp), 0.0, 1e-6);            // a gradient is no glint
  EXPECT_GT(glint_detail(sparse) / detail, 1.8);          // 4x brighter, 4x fewer: about 2x
  // A tile's mean off by 1 in one of the 16 tiles: block RMSE sqrt(1 / 16).
  Image shifted = other;
  for (int y = 0; y < block; ++y)
    for (int x = 0; x < block; ++x) shifted.at(x, y) += glm::vec3(1.0f);
  EXPECT_NEAR(block_rmse(shifted, reference, block), 0.25, 1e-6);
  // A noisy estimate of the reference (white noise of standard deviation 2, stated as its
  // standard error): the noise adds to its detail, and taking the stated noise out gives it back.
  std::mt19937 random(7);
  std::normal_distribution<float> normal(0.0f, 2.0f);
  Image noisy = reference;
  for (glm::vec3& p : noisy.pixels()) p += glm::vec3(normal(random));
  const Image standard_error(size, size, glm::vec3(2.0f));
  std::printf("glint detail / the reference's: other %.4f, sparse %.4f, a noisy estimate %.4f (noise taken out %.4f)\n",
              glint_detail(other) / detail, glint_detail(sparse) / detail, glint_detail(noisy) / detail,
              glint_detail(noisy, &standard_error) / detail);
  EXPECT_GT(glint_detail(noisy) / detail, 1.07);
  EXPECT_NEAR(glint_detail(noisy, &standard_error) / detail, 1.0, 0.06);
  EXPECT_THROW(block_rmse(other, reference, 0), std::invalid_argument);
}
