// Yan et al. 2016's position-normal distribution on the CPU (src/prefilter/position_normal.hpp):
// identities at its limits, its mass, and its distance to the surface it approximates.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "prefilter/position_normal.hpp"

namespace glintlab {
namespace {

NormalMap uniform_map(int size, glm::vec3 n) {
  return {size, size, std::vector<glm::vec3>(static_cast<std::size_t>(size * size), glm::normalize(n)), "uniform"};
}

double gaussian(glm::dvec2 d, double sigma) {
  return std::exp(-0.5 * glm::dot(d, d) / (sigma * sigma)) / (glm::two_pi<double>() * sigma * sigma);
}

glm::dvec2 centroid(const NdfImage& img) {
  glm::dvec2 sum(0.0);
  double mass = 0.0;
  for (int j = 0; j < img.grid.resolution; ++j)
    for (int i = 0; i < img.grid.resolution; ++i) {
      sum += static_cast<double>(img.at(i, j)) * img.grid.pixel_centre(i, j);
      mass += img.at(i, j);
    }
  return sum / mass;
}

TEST(PositionNormal, UniformMapIsTheIntrinsicGaussianAboutItsNormal) {
  const glm::vec3 n0 = glm::normalize(glm::vec3(0.2f, -0.1f, 1.0f));
  const NormalMap map = uniform_map(16, n0);
  for (int k : {1, 2}) {
    const PositionNormalDistribution pnd(map, 0.03, k);
    for (double sigma : {0.01, 1.0, 7.0}) {
      const Footprint f = Footprint::isotropic({5.3, 9.1}, sigma);
      for (glm::dvec2 s : {glm::dvec2(n0), glm::dvec2(0.25, -0.05), glm::dvec2(0.1, -0.15)})
        EXPECT_NEAR(pnd.density(f, s), gaussian(s - glm::dvec2(n0), 0.03), 1e-6 * gaussian({0, 0}, 0.03))
            << "k " << k << " sigma " << sigma;
    }
  }
}

TEST(PositionNormal, ImagesHoldTheWholeMassAndRangeMeansAverageTheDensity) {
  const NormalMap map = generate_bumps(64, 0.25f, 64, 12, 3);
  const PositionNormalDistribution pnd(map, 0.02, 1);
  const NdfGrid grid{64, pnd.suggested_extent()};
  for (double sigma : {0.3, 2.0, 9.0}) {
    const Footprint f = Footprint::isotropic({20.5, 31.2}, sigma);
    EXPECT_NEAR(pnd.image(f, grid).mass(), 1.0, 1e-3) << "sigma " << sigma;
    // A box's mean against the mean of the density over a fine grid of the box.
    const glm::dvec2 lo(-0.12, -0.05), hi(0.07, 0.11);
    double sum = 0.0;
    const int n = 96;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) sum += pnd.density(f, lo + (hi - lo) * (glm::dvec2(i, j) + 0.5) / double(n));
    const double grid_mean = sum / (n * n);
    EXPECT_NEAR(pnd.range_mean(f, lo, hi), grid_mean, 2e-3 * grid_mean + 1e-4) << "sigma " << sigma;
  }
}

TEST(PositionNormal, CentroidIsTheFootprintsMeanNormal) {
  // E_P[s] = sum_e w_e mean_e / sum_e w_e: the mean projected normal the footprint sees, which the
  // surface itself gives by Monte Carlo; the elements approximate the bilinear field.
  const NormalMap map = generate_flakes(64, 8, 0.2f, 5);
  const PositionNormalDistribution pnd(map, 0.01, 2);
  const NdfGrid grid{96, pnd.suggested_extent()};
  for (double sigma : {1.0, 4.0}) {
    const Footprint f = Footprint::isotropic({17.0, 40.0}, sigma);
    const glm::dvec2 yan = centroid(pnd.image(f, grid));
    const glm::dvec2 surface = centroid(surface_ndf_histogram(map, 0.01, f, grid, 400000, 7));
    EXPECT_NEAR(yan.x, surface.x, 0.01) << "sigma " << sigma;
    EXPECT_NEAR(yan.y, surface.y, 0.01) << "sigma " << sigma;
  }
}

TEST(PositionNormal, ElementsApproximateTheSurfaceAndTwoPerTexelBetter) {
  // The NDF image of the elements against the surface's own NDF (Monte Carlo): close, and closer
  // with 2 x 2 elements per texel than with one.
  const NormalMap map = generate_bumps(64, 0.3f, 96, 16, 11);
  const Footprint f = Footprint::isotropic({30.0, 12.5}, 2.5);
  const PositionNormalDistribution one(map, 0.015, 1), two(map, 0.015, 2);
  const NdfGrid grid{48, one.suggested_extent()};
  const NdfImage surface = surface_ndf_histogram(map, 0.015, f, grid, 2000000, 3);
  const double e1 = relative_l2(one.image(f, grid), surface), e2 = relative_l2(two.image(f, grid), surface);
  std::printf("relative L2 to the surface: k=1 %.4f, k=2 %.4f\n", e1, e2);
  EXPECT_LT(e2, e1);
  EXPECT_LT(e2, 0.15);
}

}  // namespace
}  // namespace glintlab
