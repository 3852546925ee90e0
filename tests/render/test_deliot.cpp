// deliot2023 in the renderer (docs/methods.md#deliot2023): convergence to the smooth GGX render at
// high density (method and reference), the mean over many pixels against the smooth render where
// about one facet reflects (the lognormal count unbiased, the paper's Gaussian not), glints
// attached to the surface and deterministic.
#include <gtest/gtest.h>

#include <cmath>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "glint_convergence.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A flat binomial-glints patch seen straight down by an orthographic camera (size x size pixels,
// 1 / size uv per pixel); a point light above it spreads the lobe over the patch, a directional
// one gives every pixel the same half vector. camera_x shifts the camera along +x.
TestScene flat_patch(double log_density, bool directional, double camera_x = 0.0, int size = 64) {
  TestScene s;
  s.film(size, size)
      .orthographic_camera({camera_x, 3, 0}, {camera_x, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
      .material("glitter", {{"type", "binomial-glints"},
                            {"alpha", {0.2, 0.14}},
                            {"log_density", log_density},
                            {"microfacet_roughness", 0.02},
                            {"slope_grid_scale", 12},
                            {"f0", 0.9}})
      .plane("glitter", {{"size", 4}, {"uv_scale", 2}});
  if (directional)
    s.directional_light({-0.15, -1.0, -0.1}, 1);
  else
    s.point_light({0.1, 1.0, 0.05}, 1);
  return s;
}

TEST(Deliot, DenseGlintsConvergeToTheGgxRender) {
  // ln density 40: ~1e14 facets per grid cell. `conventional` shades the material's smooth GGX.
  SceneFixture dense(flat_patch(40.0, false));
  const Frame smooth = dense.method("conventional");
  expect_matches_smooth(dense.method("deliot2023").specular, smooth.specular, "deliot2023");
  expect_matches_smooth(dense.method("deliot2023", {{"remaining_count", "gaussian"}}).specular, smooth.specular,
                        "deliot2023, the paper's Gaussian count");
  // Sparse glints are not the smooth lobe pixel by pixel (the test can fail).
  SceneFixture sparse(flat_patch(10.0, false));
  EXPECT_GT(rmse(sparse.method("deliot2023").specular, smooth.specular),
            5.0 * rmse(dense.method("deliot2023").specular, smooth.specular));
}

TEST(Deliot, DenseGlintsConvergeToTheGgxRenderInTheReference) {
  // The reference's own path (the glinty BRDF at each sub-pixel's footprint) against the smooth
  // material's reference, both under a delta light.
  SceneFixture dense(flat_patch(40.0, false, 0.0, 32));
  const Image glinty = dense.reference(4).specular;
  dense.scene.materials[0].set_kind(default_material_kind());  // its smooth limit
  SceneFixture smooth(dense.scene);
  expect_matches_smooth(glinty, smooth.reference(4).specular, "reference");
}

TEST(Deliot, MeanOverManyPixelsIsTheSmoothRenderWhereAboutOneFacetReflects) {
  // ln density 14: ~100 facets per cell, n p ~ 0.1 .. 2 per grid share over the lobe: E[count]
  // = n p makes the image's mean the smooth render's; the paper's Gaussian count
  // 1 + (n - 1) p given a hit makes it brighter.
  SceneFixture f(flat_patch(14.0, false, 0.0, 128));
  const double smooth = mean_luminance(f.method("conventional").specular);
  const double lognormal = mean_luminance(f.method("deliot2023").specular);
  const double gaussian = mean_luminance(f.method("deliot2023", {{"remaining_count", "gaussian"}}).specular);
  std::printf("mean specular: smooth %.5f, lognormal %.5f (%+.2f%%), paper's Gaussian %.5f (%+.2f%%)\n", smooth,
              lognormal, 100 * (lognormal / smooth - 1), gaussian, 100 * (gaussian / smooth - 1));
  EXPECT_NEAR(lognormal, smooth, 0.03 * smooth);
  EXPECT_GT(gaussian, 1.08 * smooth);
}

TEST(Deliot, GlintsAreAttachedToTheSurfaceAndDeterministic) {
  // Orthographic, straight down, a directional light: every pixel has the same half vector and
  // footprint, so the image is the glints' pattern alone. A one-pixel move of the camera moves
  // the image by one pixel; glints seeded by screen position would stay put instead.
  const double pixel = 2.0 / 64.0;
  SceneFixture still(flat_patch(11.0, true)), moved(flat_patch(11.0, true, pixel));
  const Image a = still.method("deliot2023").specular, b = moved.method("deliot2023").specular;
  EXPECT_EQ(rmse(a, still.method("deliot2023").specular), 0.0) << "same command, same image";
  const Image a_shifted = a.crop(1, 0, 63, 64), b_aligned = b.crop(0, 0, 63, 64), b_unaligned = b.crop(1, 0, 63, 64);
  const double scale = mean_luminance(a);
  ASSERT_GT(scale, 0.0);
  const double aligned = rmse(a_shifted, b_aligned), unaligned = rmse(a_shifted, b_unaligned);
  EXPECT_LT(aligned, 0.02 * scale) << "moved with the surface";
  EXPECT_GT(unaligned, 10.0 * aligned + 0.1 * scale) << "the pattern has structure at the pixel scale";
}

}  // namespace
