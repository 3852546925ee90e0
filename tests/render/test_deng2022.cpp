// deng2022 in the renderer (docs/methods.md#deng2022): the pyramid's queries against yan2016's
// exact sum on the same scene and against the Gaussian-filtered reference, near (the first level
// and the element fallback) and far (the pyramid's upper levels); lights with extent through the
// box query; other materials as conventional; no NaN for random lights. Tiny images and maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "prefilter/environment_sg_fit.hpp"
#include "scene/lights/environment_studio.hpp"
#include "scratch_directory.hpp"
#include "gl_fixture.hpp"
#include "normal_glints_floor.hpp"
#include "random_area_lights.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// The same footprints (k = 2, as the pyramid's images) summed exactly.
const std::map<std::string, std::string> kExactYan = {{"elements_per_texel", "2"}};

TEST(Deng2022, MatchesYan2016AndTheReferenceNearAndFar) {
  for (double tiling : {2.0, 24.0}) {  // about two texels a pixel; tens of texels a pixel
    for (bool area : {false, true}) {
      SceneFixture f(normal_glints_floor(tiling, area));
      const ReferenceFrame ref = footprint_filtered_reference(f, 64);
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
      // The pyramid stays closer to the elements it compresses than those are to the truth: near,
      // the fallback sums the very elements (deng-yan measured 0.047 and 0.24 against yan2016's
      // 0.47 and 1.61 from the reference; 0.64 and 1.29 with one element per texel), far the
      // compressed pyramid (0.26 and 0.68 against 0.40 and 0.96)...
      EXPECT_LT(between, (tiling < 4.0 ? 0.3 : 1.0) * yan_err) << "tiling " << tiling << (area ? " area" : "");
      // ...and keep the energy yan2016 has.
      EXPECT_NEAR(energy_ratio(deng, yan), 1.0, 0.08) << "tiling " << tiling << (area ? " area" : "");
    }
  }
}

// A grazing view: footprints up to 20 times longer than wide. One isotropic query of the
// footprint's area blurs them across and cuts them along; isotropic probes along the major axis
// keep both. yan2016 (k = 2, the pyramid's own elements; max_elements 60000: every element of
// these footprints, or a stratified subset past it) sums each footprint in its true shape. (The probes against the exact P-NDF
// query by query: PrefilteredNdfGlsl.ProbesAlongTheMajorAxis...; against the reference the element
// model's own error dominates here: issue notes in docs/methods.md#deng2022.)
TEST(Deng2022, ProbesAlongTheMajorAxisKeepAnisotropicFootprintsShape) {
  for (double tiling : {2.0, 4.0}) {
    Scene scene = normal_glints_floor(tiling, false, 64, 24).scene();
    scene.camera.position = {0.0f, 0.12f, 1.6f};
    scene.camera.target = {0.0f, 0.0f, -1.5f};
    scene.lights[0].position = {0.0f, 0.35f, -2.5f};
    SceneFixture f(std::move(scene));
    const Image yan = f.method("yan2016", {{"elements_per_texel", "2"}, {"max_elements", "60000"}}).total;
    const Image probes = f.method("deng2022").total, one = f.method("deng2022", {{"anisotropic_probes", "1"}}).total;
    std::printf("grazing, tiling %g: rmse to yan2016: probes %.4f, one query %.4f; energy probes/yan %.4f, one/yan %.4f\n",
                tiling, rmse(probes, yan), rmse(one, yan), energy_ratio(probes, yan), energy_ratio(one, yan));
    EXPECT_LT(rmse(probes, yan), 0.8 * rmse(one, yan)) << "tiling " << tiling;  // measured: 0.42 and 0.54 of it
    EXPECT_NEAR(energy_ratio(probes, yan), 1.0, 0.1) << "tiling " << tiling;
  }
}

TEST(Deng2022, TheElementFallbackIsYan2016BelowTheFirstLevel) {
  // Magnified (a texel over several pixels): every footprint is finer than the first level, so
  // deng2022 sums the elements exactly as yan2016 with k = 2 (the pyramid's own elements) does.
  SceneFixture f(normal_glints_floor(0.25, false));
  const Image deng = f.method("deng2022").total, yan = f.method("yan2016", kExactYan).total;
  EXPECT_LT(rmse(deng, yan), 1e-5);
  // Clamped to the first level instead, it blurs: further from yan2016.
  const Image clamped = f.method("deng2022", {{"small_footprints", "clamp"}}).total;
  EXPECT_GT(rmse(clamped, yan), 10 * rmse(deng, yan) + 1e-6);
}

// Under an environment alone, deng2022 by its spherical Gaussian lobes (sec. 5.4; each lobe box
// queries of the footprint's NDF over nested cones) against the reference under the lobes' own
// radiance (the studio map's lattice lobes, written out as a map: the truth of the lobes' shading,
// apart from the fit's error, which tests/prefilter reports) and against the same method shading
// the environment as the material's smooth lobe (environment_lobes = 0).
TEST(Deng2022, AnEnvironmentByItsLobes) {
  ScratchDirectory scratch;
  const EnvironmentMap studio = studio_environment_map(128);
  // The lattice's lobes alone (the sun's lobe is far sharper than a texel).
  const SphericalGaussianFit fit = fit_spherical_gaussians(studio, 32, 64).without_peaks();
  const EnvironmentMap lobes_map = fit.to_map(64);
  write_exr(scratch / "lobes.exr", {{"", &lobes_map.radiance}});
  for (double tiling : {2.0, 24.0}) {
    SceneFixture f(normal_glints_floor_unlit(tiling).light(
        "environment", {{"file", (scratch / "lobes.exr").string()}, {"visible", false}}));
    const ReferenceFrame ref = footprint_filtered_reference(f, 64);
    const Image lobes = f.method("deng2022").total;
    const Image smooth = f.method("deng2022", {{"environment_lobes", "0"}}).total;
    const Image one_cone = f.method("deng2022", {{"environment_lobe_cones", "one"}}).total;
    const Image yan = f.method("yan2016", kExactYan).total;  // the same lobes summed over the elements
    ASSERT_EQ(lobes.count_non_finite(), 0u);
    ASSERT_EQ(yan.count_non_finite(), 0u);
    const double lobes_err = rmse(lobes, ref.mean.total), smooth_err = rmse(smooth, ref.mean.total);
    std::printf("tiling %g, the studio's 32 lobes: rmse lobes %.4f (one cone each %.4f), smooth lobe %.4f, lean %.4f, "
                "yan2016 %.4f, noise %.4f, energy lobes %.4f smooth %.4f yan2016 %.4f\n",
                tiling, lobes_err, rmse(one_cone, ref.mean.total), smooth_err, rmse(f.method("lean").total, ref.mean.total),
                rmse(yan, ref.mean.total),
                ref.noise_rmse(), energy_ratio(lobes, ref.mean.total), energy_ratio(smooth, ref.mean.total),
                energy_ratio(yan, ref.mean.total));
    // yan2016 sums the same lobes' queries over the elements: deng2022 stays near it.
    EXPECT_NEAR(energy_ratio(lobes, yan), 1.0, 0.05) << "tiling " << tiling;
    // The cones keep the lobes' energy (measured 0.963 near, 0.965 far; the smooth lobe 1.26,
    // 1.21)...
    EXPECT_NEAR(energy_ratio(lobes, ref.mean.total), 1.0, 0.06) << "tiling " << tiling;
    EXPECT_LT(std::abs(energy_ratio(lobes, ref.mean.total) - 1.0), std::abs(energy_ratio(smooth, ref.mean.total) - 1.0))
        << "tiling " << tiling;
    // ...and far, where a pixel's footprint holds many glints, the image is nearer the truth (0.072
    // against 0.115; near, 0.178 against 0.174: the footprint's NDF is a few sharp glints there,
    // and a lobe's cones spread each one's light evenly over a ring).
    if (tiling > 4.0) {
      EXPECT_LT(lobes_err, 0.85 * smooth_err);
    }
  }
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
    TestScene s = normal_glints_floor(trial == 0 ? 1.0 : 16.0, false);
    add_random_area_lights(s, rng, trial);
    SceneFixture f(s);
    ASSERT_EQ(f.method("deng2022").total.count_non_finite(), 0u) << "trial " << trial;
  }
}

}  // namespace

namespace {

// deng2022's pyramids are a resource (src/render/resources/): made once per scene and precompute
// settings, kept while the scene lives, within the size estimated before they are made.
TEST(Resources, APrefilteredNdfIsMadeOncePerSettingsWithinItsEstimate) {
  SceneFixture f(normal_glints_floor(2.0, false, 16, 12));
  const MethodDescriptor& deng = find_method("deng2022");
  ResourceSet& resources = f.gpu->resources();
  const std::vector<std::string> ids = method_resources(deng, resolve_params(deng, {}));
  ASSERT_NE(std::find(ids.begin(), ids.end(), "prefiltered-ndf"), ids.end());
  const ParamValues defaults = resolve_params(deng, {}), rank8 = resolve_params(deng, {{"rank", "8"}});
  EXPECT_EQ(resources.find("prefiltered-ndf", f.gpu->resource_context(defaults)), nullptr) << "made on first use";
  (void)f.method("deng2022");
  const GpuResource* made = resources.find("prefiltered-ndf", f.gpu->resource_context(defaults));
  ASSERT_NE(made, nullptr);
  (void)f.method("deng2022");
  EXPECT_EQ(resources.find("prefiltered-ndf", f.gpu->resource_context(defaults)), made) << "kept, not remade";
  EXPECT_EQ(resources.find("prefiltered-ndf", f.gpu->resource_context(rank8)), nullptr) << "other settings: another";
  const std::uint64_t estimate =
      estimate_resource_bytes({"prefiltered-ndf"}, f.gpu->resource_context(defaults));
  EXPECT_GT(made->gpu_bytes(), 0u);
  EXPECT_LE(made->gpu_bytes(), estimate) << "the estimate bounds it";
  EXPECT_THROW(find_resource_type("no-such-resource"), InputError);
}

}  // namespace
