// Ray cones (path/ray_cone.hpp): the widening of footprints after rough bounces. The cone's growth
// is the sum of its lobes' spreads times the distances travelled since each; the widened
// footprint's covariance is the footprint's plus the cone's cross-section projected along the ray
// onto the surface, which is wider by 1 / cos along the plane of incidence.
#include <gtest/gtest.h>

#include <cmath>

#include "path/ray_cone.hpp"

using namespace glintlab;

namespace {

glm::mat3 covariance(glm::vec3 a, glm::vec3 b) { return glm::outerProduct(a, a) + glm::outerProduct(b, b); }

void expect_near(const glm::mat3& a, const glm::mat3& b, float tolerance) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[i][j], b[i][j], tolerance) << i << ", " << j;
}

}  // namespace

TEST(RayCone, WidthGrowsByEachLobesSpreadTimesTheDistanceSinceIt) {
  // Two rough bounces: spreads 0.1 then 0.3, distances 2 then 0.5 after each.
  const RayCone cone = RayCone{}.bounced(0.1f).travelled(2.0f).bounced(0.3f).travelled(0.5f);
  EXPECT_NEAR(cone.width, 0.1f * 2.5f + 0.3f * 0.5f, 1e-6f);
  EXPECT_NEAR(cone.spread, 0.4f, 1e-6f);
  EXPECT_EQ(RayCone{}.travelled(10.0f).width, 0.0f);  // a camera ray's own footprint is its differentials
  EXPECT_NEAR(lobe_spread(0.1f, false), std::sqrt(2.0f) * 0.1f, 1e-7f);
  EXPECT_EQ(lobe_spread(0.0f, false), 0.0f);  // a mirror keeps the cone
  EXPECT_EQ(lobe_spread(2.0f, false), 0.5f);  // no wider than a diffuse lobe
  EXPECT_EQ(lobe_spread(0.1f, true), 0.5f);
}

TEST(RayCone, TheWidenedFootprintAddsTheProjectedCrossSection) {
  const glm::vec3 n(0, 1, 0), dPdx(0.02f, 0, 0.01f), dPdy(-0.005f, 0, 0.03f);
  const float width = 0.1f, sigma = 0.5f, step = width / sigma;
  // Head on: the cross-section is a disc of deviation `width` on the plane, steps of width / sigma.
  {
    const auto [x, y] = widen_footprint(dPdx, dPdy, -n, n, width, sigma);
    glm::mat3 expected = covariance(dPdx, dPdy) + step * step * (glm::mat3(1.0f) - glm::outerProduct(n, n));
    expect_near(covariance(x, y), expected, 1e-6f);
    EXPECT_NEAR(glm::dot(x, n), 0.0f, 1e-7f);
    EXPECT_NEAR(glm::dot(y, n), 0.0f, 1e-7f);
    EXPECT_NEAR(glm::dot(x, y), 0.0f, 1e-7f);  // principal axes
  }
  // At 60 degrees from the normal in the xy plane: 1 / cos = 2 times longer along x, as wide along z.
  {
    const glm::vec3 d = glm::normalize(glm::vec3(std::sin(1.0471976f), -std::cos(1.0471976f), 0.0f));
    const auto [x, y] = widen_footprint(glm::vec3(0.0f), glm::vec3(0.0f), d, n, width, sigma);
    glm::mat3 expected(0.0f);
    expected[0][0] = 4.0f * step * step;
    expected[2][2] = step * step;
    expect_near(covariance(x, y), expected, 1e-5f);
  }
  // No cone: the steps as they were.
  const auto [x, y] = widen_footprint(dPdx, dPdy, -n, n, 0.0f, sigma);
  EXPECT_EQ(x, dPdx);
  EXPECT_EQ(y, dPdy);
}
