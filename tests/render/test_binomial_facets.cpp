// The raster-facets reference in the renderer (docs/methods.md#kneiphof2024, "A surface of
// facets"): dense facets are the smooth material's reference at every alpha, under lights with
// extent and a delta light, within the two references' stated errors; sparse ones are not; and
// the surface is one surface, the same at every resolution, where the counting model's reference
// draws its glints afresh for each footprint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "glint_convergence.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A flat binomial-glints patch (no diffuse) seen straight down, 2 uv units across the film, under
// a quad, a disk and a point light.
TestScene facet_patch(double alpha, double log_density, int size) {
  TestScene s;
  s.film(size, size)
      .orthographic_camera({0, 3, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
      .material("glitter", {{"type", "binomial-glints"},
                            {"alpha", alpha},
                            {"log_density", log_density},
                            {"microfacet_roughness", 0.1},
                            {"f0", 0.9},
                            {"diffuse", 0.0}})
      .plane("glitter", {{"size", 4}, {"uv_scale", 2}})
      .light("quad", {{"position", {0.2, 1.2, 0.1}},
                      {"direction", {0, -1, 0}},
                      {"size", {0.8, 0.4}},
                      {"up", {0, 0, 1}},
                      {"radiance", {2, 1.5, 1}}})
      .disk_light({-0.5, 0.9, -0.3}, {0.3, -1, 0.2}, 0.15, {4, 5, 6})
      .point_light({0.4, 1.5, -0.5}, 1.5);
  return s;
}

ReferenceFrame facets_reference(SceneFixture& f, int spp) {
  auto backend = make_reference_backend("raster-facets", {shaders(), *f.gpu, *f.renderer});
  ReferenceSettings settings;
  settings.spp = spp;
  return render_reference(*backend, f.scene.camera, f.scene.film.width, f.scene.film.height, settings);
}

// Mean luminance of an 8 x 8 block and its stated error (the pixels' stated errors, independent).
std::pair<double, double> block_with_error(const ReferenceFrame& r, int bx, int by) {
  const Image stated = r.stated_error();
  double sum = 0, variance = 0;
  for (int y = by; y < by + 8; ++y)
    for (int x = bx; x < bx + 8; ++x) {
      sum += luminance(r.mean.total.at(x, y));
      const double e = luminance(stated.at(x, y));
      variance += e * e;
    }
  return {sum / 64, std::sqrt(variance) / 64};
}

}  // namespace

TEST(BinomialFacets, DenseFacetsAreTheSmoothMaterialAtEveryAlpha) {
  for (double alpha : {0.05, 0.2, 0.5}) {
    SceneFixture dense(facet_patch(alpha, 40.0, 32));
    const ReferenceFrame facets = facets_reference(dense, 4096);
    dense.scene.materials[0].set_kind(default_material_kind());  // its smooth limit
    SceneFixture smooth_fixture(dense.scene);
    const ReferenceFrame smooth = smooth_fixture.reference_estimate(256);
    const double ratio = mean_luminance(facets.mean.total) / mean_luminance(smooth.mean.total);
    // Both errors are stated for ~95% coverage at two of them; the facets' own bias is (b / alpha)^2.
    const double stated = std::hypot(facets.relative_energy_error(), smooth.relative_energy_error());
    std::printf("alpha %.2f: facets / smooth energy %.4f (stated errors %.4f facets, %.4f smooth)\n", alpha, ratio,
                facets.relative_energy_error(), smooth.relative_energy_error());
    EXPECT_NEAR(ratio, 1.0, 2 * stated + 1e-3) << "alpha " << alpha;
    int blocks = 0, outside = 0;
    for (int by = 0; by < 32; by += 8)
      for (int bx = 0; bx < 32; bx += 8) {
        const auto [f, fe] = block_with_error(facets, bx, by);
        const auto [s, se] = block_with_error(smooth, bx, by);
        ++blocks;
        outside += std::abs(f - s) > 2 * std::hypot(fe, se) + 1e-3 * s;
      }
    // About 5% of blocks may lie outside two stated errors; 4 of 16 would say the facets are biased.
    EXPECT_LE(outside, 3) << "alpha " << alpha << ": blocks outside two stated errors";
  }
}

TEST(BinomialFacets, SparseFacetsAreGlintsNotTheSmoothLobe) {
  // About 12 facets a pixel (ln density 8): each pixel's few facets, far from the smooth lobe
  // beyond the reference's noise (the test above can fail).
  SceneFixture sparse(facet_patch(0.2, 8.0, 32));
  const ReferenceFrame facets = facets_reference(sparse, 64);
  sparse.scene.materials[0].set_kind(default_material_kind());
  SceneFixture smooth(sparse.scene);
  const Image reference = smooth.reference(64).total;
  EXPECT_GT(rmse(facets.mean.total, reference), 5 * facets.noise_rmse());
}

TEST(BinomialFacets, TheSurfaceIsTheSameAtEveryResolution) {
  // Facets about 2 pixels across at 32 x 32 (ln density 4: 7.4 per uv unit, 16 pixels a unit):
  // the 64 x 64 render averaged 2 x 2 is the 32 x 32 render within the references' noise. The
  // counting model's reference draws other glints for other footprints, so it is not.
  auto at = [](int size, const char* backend) {
    SceneFixture f(facet_patch(0.2, 4.0, size));
    auto b = make_reference_backend(backend, {shaders(), *f.gpu, *f.renderer});
    ReferenceSettings settings;
    settings.spp = 64;
    return render_reference(*b, f.scene.camera, size, size, settings);
  };
  auto halve = [](const Image& img) {
    Image out(img.width() / 2, img.height() / 2);
    for (int y = 0; y < out.height(); ++y)
      for (int x = 0; x < out.width(); ++x)
        out.at(x, y) = 0.25f * (img.at(2 * x, 2 * y) + img.at(2 * x + 1, 2 * y) + img.at(2 * x, 2 * y + 1) +
                                img.at(2 * x + 1, 2 * y + 1));
    return out;
  };
  const ReferenceFrame coarse = at(32, "raster-facets"), fine = at(64, "raster-facets");
  const double facets_gap = rmse(coarse.mean.total, halve(fine.mean.total));
  const double noise = std::hypot(coarse.noise_rmse(), 0.5 * fine.noise_rmse());
  const ReferenceFrame counting_coarse = at(32, "raster"), counting_fine = at(64, "raster");
  const double counting_gap = rmse(counting_coarse.mean.total, halve(counting_fine.mean.total));
  std::printf("32 against 64 averaged 2x2: facets rmse %.4f (noise %.4f), counting reference %.4f\n", facets_gap, noise,
              counting_gap);
  EXPECT_LT(facets_gap, 2 * noise);
  EXPECT_GT(counting_gap, 3 * facets_gap);
}
