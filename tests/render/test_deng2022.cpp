// deng2022 in the renderer (docs/methods.md#deng2022): the pyramid's queries against yan2016's
// exact sum on the same scene and against the Gaussian-filtered reference, near (the first level
// and the element fallback) and far (the pyramid's upper levels); lights with extent through the
// box query; other materials as conventional; no NaN for random lights. Tiny images and maps.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "random_area_lights.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A receding normal-map-glints floor (a 64^2 bumps map, `tiling` repeats over the 4 m plane) under
// a point light, or under a sphere and a disk light.
TestScene floor_scene(double tiling, bool area_lights) {
  TestScene s;
  s.film(48, 32)
      .camera({0, 0.6, 1.6}, {0, 0, -0.8}, 40)
      .material("steel", {{"type", "normal-map-glints"},
                          {"intrinsic_roughness", 0.02},
                          {"f0", 0.9},
                          {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.25},
                                                  {"waves", 48}, {"max_frequency", 8}, {"seed", 3}}},
                          {"normal_map_tiling", tiling}})
      .plane("steel", {{"size", 4}});
  if (area_lights)
    s.sphere_light({0.4, 0.9, -1.6}, 0.08, {300, 300, 300}, {{"visible", false}})
        .disk_light({-0.6, 0.7, -1.2}, {0.3, -1, 0.4}, 0.1, {200, 250, 300}, {{"visible", false}});
  else
    s.point_light({0.3, 1.0, -1.8}, 3);
  return s;
}

ReferenceFrame filtered_reference(SceneFixture& f, int spp) {
  ReferenceSettings settings;
  settings.spp = spp;
  settings.filter = PixelFilter::gaussian(0.5);
  return f.reference_at(f.scene.camera, f.scene.film.width, f.scene.film.height, settings);
}

// The same footprints (k = 2, as the pyramid's images) summed exactly.
const std::map<std::string, std::string> kExactYan = {{"elements_per_texel", "2"}};

TEST(Deng2022, MatchesYan2016AndTheReferenceNearAndFar) {
  for (double tiling : {2.0, 24.0}) {  // about two texels a pixel; tens of texels a pixel
    for (bool area : {false, true}) {
      SceneFixture f(floor_scene(tiling, area));
      const ReferenceFrame ref = filtered_reference(f, 64);
      const Image deng = f.method("deng2022").total, yan = f.method("yan2016", kExactYan).total;
      const Image lean = f.method("lean").total;
      const double deng_err = rmse(deng, ref.mean.total), yan_err = rmse(yan, ref.mean.total);
      const double lean_err = rmse(lean, ref.mean.total), between = rmse(deng, yan);
      std::printf("tiling %g, %s: rmse deng2022 %.4f, yan2016 %.4f, lean %.4f, deng-yan %.4f, noise %.4f, "
                  "energy deng %.4f yan %.4f\n",
                  tiling, area ? "area lights" : "point light", deng_err, yan_err, lean_err, between,
                  ref.noise_rmse(), energy_ratio(deng, ref.mean.total), energy_ratio(yan, ref.mean.total));
      ASSERT_EQ(deng.count_non_finite(), 0u);
      // The compression and interpolation cost little next to the model's own error...
      EXPECT_LT(deng_err, 1.35 * yan_err + 2 * ref.noise_rmse()) << "tiling " << tiling << (area ? " area" : "");
      // ...and keep the energy yan2016 has.
      EXPECT_NEAR(energy_ratio(deng, yan), 1.0, 0.08) << "tiling " << tiling << (area ? " area" : "");
    }
  }
}

TEST(Deng2022, TheElementFallbackIsYan2016BelowTheFirstLevel) {
  // Magnified (a texel over several pixels): every footprint is finer than the first level, so
  // deng2022 sums the elements exactly as yan2016 with k = 1 does.
  SceneFixture f(floor_scene(0.25, false));
  const Image deng = f.method("deng2022").total, yan = f.method("yan2016").total;
  EXPECT_LT(rmse(deng, yan), 1e-5);
  // Clamped to the first level instead, it blurs: further from yan2016.
  const Image clamped = f.method("deng2022", {{"small_footprints", "clamp"}}).total;
  EXPECT_GT(rmse(clamped, yan), 10 * rmse(deng, yan) + 1e-6);
}

TEST(Deng2022, OtherMaterialsAreConventional) {
  TestScene s;
  s.film(32, 24).camera({0, 0.8, 2.0}, {0, 0, 0}, 40).material("m", {{"alpha", 0.2}}).sphere("m").point_light({1, 2, 2}, 5);
  SceneFixture f(s);
  EXPECT_EQ(f.method("deng2022").total.pixels(), f.method("conventional").total.pixels());
}

TEST(Deng2022, NoNanUnderRandomLights) {
  std::mt19937 rng(40);
  for (int trial = 0; trial < 2; ++trial) {
    TestScene s = floor_scene(trial == 0 ? 1.0 : 16.0, false);
    add_random_area_lights(s, rng, trial);
    SceneFixture f(s);
    ASSERT_EQ(f.method("deng2022").total.count_non_finite(), 0u) << "trial " << trial;
  }
}

}  // namespace
