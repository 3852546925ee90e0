#include <gtest/gtest.h>

#include <cmath>

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
