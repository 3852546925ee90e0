// kemppinen2025 and the point-process-glints material in the renderer (docs/methods.md#kemppinen2025):
// dense glints converge to the smooth GGX render, in the method and in the reference (whose lights
// with extent are integrated by MIS with the NDF's own sampler); sparse ones do not; the method's
// energy is the reference's, a realisation apart.
#include <gtest/gtest.h>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "glint_convergence.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A flat point-process-glints patch (or, `smooth`, its smooth limit: a microfacet GGX material)
// seen straight down (48 x 48 pixels) under a point light and, `disk`, a disk light, whose lobes
// spread over the patch.
TestScene glitter_patch(double log_density, bool disk, bool smooth = false) {
  TestScene s;
  TomlKeys material = {{"alpha", 0.25}, {"f0", 0.9}};
  if (!smooth) {
    material.push_back({"type", "point-process-glints"});
    material.push_back({"log_density", log_density});
    material.push_back({"microfacet_roughness", 0.02});
  }
  s.film(48, 48)
      .orthographic_camera({0, 3, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
      .material("glitter", material)
      .plane("glitter", {{"size", 4}, {"uv_scale", 2}})
      .point_light({0.3, 1.5, 0.2}, 3.0);
  if (disk) s.disk_light({-0.5, 0.9, -0.3}, {0.3, -1, 0.2}, 0.15, {4, 5, 6});
  return s;
}

TEST(PointProcessRender, DenseGlintsConvergeToTheSmoothRenderInTheMethodAndTheReference) {
  // ln density 30: about 3e6 facets per uv unit along each axis. The reference integrates the disk
  // light by MIS of the light and of the NDF's own sampler.
  SceneFixture dense(glitter_patch(30.0, true)), smooth(glitter_patch(30.0, true, true));
  expect_matches_smooth(dense.reference(4).specular, smooth.reference(4).specular, "reference");
  // The method shades a disk light as a point at its centre: against the smooth lobe under the
  // point light alone.
  SceneFixture dense_point(glitter_patch(30.0, false)), sparse_point(glitter_patch(10.0, false));
  const Image conventional = dense_point.method("conventional").specular;
  const Image method = dense_point.method("kemppinen2025").specular;
  expect_matches_smooth(method, conventional, "kemppinen2025");
  // Sparse glints are not the smooth lobe pixel by pixel (the test can fail).
  EXPECT_GT(rmse(sparse_point.method("kemppinen2025").specular, conventional), 5.0 * rmse(method, conventional));
}

TEST(PointProcessRender, TheMethodsEnergyIsTheReferences) {
  // Glints a few per pixel: method and reference are realisations of the same statistics (at the
  // pixel's and the sub-pixels' footprints), their means over the patch the same within a few %.
  SceneFixture f(glitter_patch(14.0, false));
  const ReferenceFrame reference = f.reference_estimate(16);
  const Frame method = f.method("kemppinen2025");
  const double ratio = energy_ratio(method.specular, reference.mean.specular);
  EXPECT_NEAR(ratio, 1.0, 0.06) << "reference energy error +-" << reference.relative_energy_error(true);
}

}  // namespace
