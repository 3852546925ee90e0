// The backends `path:<method>`: the path tracer with normal-map-glints materials as a method's
// footprint NDF (Deng et al. 2022's offline renderer: secs. 5.1, 5.2, 5.4). Under a point light a
// sample through the pixel's centre is the raster method's pixel; under a light with extent the
// MIS of the light's samples and the footprint NDF's own samples integrates what the method
// evaluates (a wrong sampling density biases it); under an environment the lobes give the
// sampled integral's value with far less noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "gl_fixture.hpp"
#include "normal_glints_floor.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "prefilter/environment_sg_fit.hpp"
#include "scene/lights/environment_studio.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

std::unique_ptr<ReferenceBackend> backend(SceneFixture& f, const std::string& id) {
  return make_reference_backend(id, {shaders(), *f.gpu, *f.renderer});
}

ReferenceFrame render_with(SceneFixture& f, const std::string& id, int spp, int light_samples = 0, int max_depth = 1) {
  ReferenceSettings s;
  s.spp = spp;
  s.light_samples = light_samples;
  s.max_depth = max_depth;
  return render_reference(*backend(f, id), f.scene.camera, f.scene.film.width, f.scene.film.height, s);
}

double mean_of(const Image& image) {
  double sum = 0;
  for (const glm::vec3& p : image.pixels()) sum += p.r + p.g + p.b;
  return sum / (3.0 * static_cast<double>(image.pixels().size()));
}

double relative_rmse(const Image& a, const Image& b) { return rmse(a, b) / mean_of(b); }

// One sample per pixel through its centre: the raster pass's sample point, so that the footprint
// (one sub-pixel, the pixel) and the point are the method's.
Frame centre_samples(SceneFixture& f, const std::string& id) {
  ReferencePass pass;
  pass.subpixels = 1;
  pass.light_samples = 1;
  pass.jitter = glm::vec2(0.5f);
  return backend(f, id)->render_pass(f.scene.camera, f.scene.film.width, f.scene.film.height, pass);
}

// Seen from straight above through an orthographic camera, the plane's attributes are affine in
// the film: the rasteriser's finite differences are the ray differentials, so the footprints are
// equal and each pixel's centre sample is the raster method's pixel, up to float rounding.
TEST(PathMethods, UnderAPointLightEachPixelCentreIsTheRasterMethods) {
  for (const double tiling : {2.0, 8.0}) {  // about 2 and 8 texels a pixel
    SceneFixture f(TestScene()
                       .film(32, 32)
                       .top_down_camera()
                       .material("steel", normal_glints_steel(tiling))
                       .plane("steel", {{"size", 4}})
                       .point_light({0.3, 1.0, 0.2}, 2.0));
    for (const std::string method : {"yan2016", "deng2022"}) {
      const Image path = centre_samples(f, "path:" + method).specular;
      const Image raster = f.method(method).specular;
      ASSERT_EQ(path.count_non_finite(), 0u) << method;
      const double error = relative_rmse(path, raster), energy = mean_of(path) / mean_of(raster);
      std::printf("%s, tiling %g: the path tracer's pixel centres against the raster's: relative rmse %.2e, energy "
                  "%.6f\n", method.c_str(), tiling, error, energy);
      EXPECT_GT(mean_of(raster), 1e-3) << method;
      EXPECT_LT(error, 1e-3) << method << ", tiling " << tiling;
      EXPECT_NEAR(energy, 1.0, 1e-4) << method << ", tiling " << tiling;
    }
  }
}

// Under a sphere light the backend samples the footprint's NDF (sec. 5.2: a probe by its weight
// times its mass, then the pyramid's sampler) beside the light: both integrate the same BRDF, so
// the estimate agrees with the method's own box query of the light (P's mean over the light's
// half-vector box, F and G at its centre) to within that query's approximation; a sampling density
// off by the half vector's Jacobian or a probe's mass would not. (yan2016's sampler shares the
// material's conversions; its own density is tested by chi-square, PositionNormalGlsl.*.)
TEST(PathMethods, SamplingTheFootprintNdfIntegratesWhatTheMethodEvaluates) {
  TestScene s = normal_glints_floor_unlit(2.0, 24, 16);
  SceneFixture f(s.sphere_light({0.4, 0.5, -1.2}, 0.4, {10, 10, 10}, {{"visible", false}}));
  const ReferenceFrame path = render_with(f, "path:deng2022", 4, 8);
  const Image raster = f.method("deng2022").specular;
  const double ratio = mean_of(path.mean.specular) / mean_of(raster);
  std::printf("deng2022 under a sphere light: path/raster energy %.4f, relative rmse %.4f\n", ratio,
              relative_rmse(path.mean.specular, raster));
  EXPECT_NEAR(ratio, 1.0, 0.05);
}

// Glinty interreflection (sec. 5.3): a glinty sphere on a glinty floor, each seen in the other.
// What a second path vertex adds is light by one rough bounce, where footprints are the camera's
// widened by the bounce's lobe (path/ray_cone.hpp): large, so deng2022 answers them from its
// pyramid. Against yan2016's brute-force sums over the same footprints and the surface itself
// (`path`, no footprint), deng2022's indirect light keeps their energy; with the same seeds, the
// first vertex's light is the same with or without the bounce.
TEST(PathMethods, GlintyInterreflectionAgreesWithTheBruteForceFootprints) {
  TestScene s = normal_glints_floor_unlit(2.0, 24, 16);
  SceneFixture f(s.sphere("steel", {{"radius", 0.35}, {"translate", {0.0, 0.35, -1.0}}, {"segments", 32}})
                     .sphere_light({0.4, 0.5, -1.2}, 0.4, {10, 10, 10}, {{"visible", false}}));
  std::map<std::string, double> indirect;
  std::map<std::string, Image> indirect_image;
  for (const std::string id : {"path:deng2022", "path:yan2016", "path"}) {
    const ReferenceFrame direct = render_with(f, id, 1024, 2, 1);
    const ReferenceFrame bounced = render_with(f, id, 1024, 2, 2);
    ASSERT_EQ(bounced.mean.total.count_non_finite(), 0u) << id;
    Image added = bounced.mean.total;
    double below = 0;  // the first vertex's light, drawn from the same streams, is not lost
    for (std::size_t i = 0; i < added.pixels().size(); ++i) {
      added.pixels()[i] -= direct.mean.total.pixels()[i];
      below = std::min<double>(below, std::min({added.pixels()[i].r, added.pixels()[i].g, added.pixels()[i].b}));
    }
    EXPECT_GT(below, -1e-4 * mean_of(direct.mean.total)) << id;
    indirect[id] = mean_of(added);
    indirect_image[id] = added;
    std::printf("%s: direct %.4f, indirect %.4f (%.1f%%)\n", id.c_str(), mean_of(direct.mean.total), indirect[id],
                100.0 * indirect[id] / mean_of(direct.mean.total));
  }
  EXPECT_GT(indirect["path"], 0.0);
  const double against_yan = indirect["path:deng2022"] / indirect["path:yan2016"];
  const double against_surface = indirect["path:deng2022"] / indirect["path"];
  const double image_error = relative_rmse(indirect_image["path:deng2022"], indirect_image["path:yan2016"]);
  std::printf("deng2022's indirect light: energy %.4f of yan2016's, %.4f of the surface's; relative rmse to yan2016's "
              "%.3f\n", against_yan, against_surface, image_error);
  EXPECT_NEAR(against_yan, 1.0, 0.1);
  EXPECT_NEAR(against_surface, 1.0, 0.15);
}

// Under an environment made of spherical Gaussians (the studio map's lattice lobes, written out as a map),
// so that the lobes hold it exactly: the lobes' range queries (sec. 5.4) give the integral that
// sampling the map and the footprint's NDF converges to, from one light sample per sub-pixel with
// a fraction of its noise (the lobes' own noise is the sub-pixels' positions alone) and nearer the
// converged image than one light sample's estimate (their bias, the cones' approximation of the
// lobe, is below that estimate's noise).
TEST(PathMethods, AnEnvironmentByLobesIsTheSampledIntegralWithLessNoise) {
  ScratchDirectory scratch;
  // The lattice's lobes alone (the sun's lobe is far sharper than a texel).
  const SphericalGaussianFit fit = fit_spherical_gaussians(studio_environment_map(128), 32, 64).without_peaks();
  const EnvironmentMap lobes_map = fit.to_map(64);
  write_exr(scratch / "lobes.exr", {{"", &lobes_map.radiance}});
  SceneFixture f(normal_glints_floor_unlit(16.0, 32, 20).light(
      "environment", {{"file", (scratch / "lobes.exr").string()}, {"visible", false}}));
  const ReferenceFrame lobes = render_with(f, "path:deng2022", 16, 1);
  const ReferenceFrame sampled = render_with(f, "path:deng2022{environment_lobes=0}", 16, 1);
  const ReferenceFrame converged = render_with(f, "path:deng2022{environment_lobes=0}", 256, 1);
  ASSERT_EQ(lobes.mean.total.count_non_finite(), 0u);
  const double energy = mean_of(lobes.mean.specular) / mean_of(converged.mean.specular);
  const double lobes_error = relative_rmse(lobes.mean.specular, converged.mean.specular);
  const double sampled_error = relative_rmse(sampled.mean.specular, converged.mean.specular);
  std::printf("the studio's 32 lobes: lobes/sampled energy %.4f; relative rmse to the converged: lobes %.4f, sampled "
              "(1 light sample) %.4f; noise lobes %.4f, sampled %.4f\n",
              energy, lobes_error, sampled_error, lobes.noise_rmse(), sampled.noise_rmse());
  EXPECT_NEAR(energy, 1.0, 0.06);
  EXPECT_LT(lobes.noise_rmse(), 0.5 * sampled.noise_rmse());
  EXPECT_LT(lobes_error, sampled_error);
}

TEST(PathMethods, OnlyMethodsWithAFootprintNdf) {
  for (const std::string id : {"path:conventional", "path:nope", "path:deng2022{rank=0}", "path:", "path:yan2016,deng2022"}) {
    try {
      (void)find_reference_backend(id);
      ADD_FAILURE() << id << " accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("--reference-backend " + id + ":"), std::string::npos) << message;
    }
  }
  EXPECT_EQ(find_reference_backend("path:deng2022{environment_lobes=0}").id, "path:deng2022{environment_lobes=0}");
  // A method's approximation judges no method; the registered backends may.
  EXPECT_FALSE(find_reference_backend("path:deng2022").ground_truth);
  EXPECT_NO_THROW(require_ground_truth_backend("path", "compare"));
  try {
    require_ground_truth_backend("path:yan2016", "compare");
    ADD_FAILURE() << "path:yan2016 accepted as compare's ground truth";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* part : {"--reference-backend path:yan2016", "compare", "allowed: raster"})
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

}  // namespace
