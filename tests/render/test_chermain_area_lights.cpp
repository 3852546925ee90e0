// Lights with extent in the Chermain glint methods (parameter light_extent,
// shaders/glints/chermain/light_kernel.glsl; docs/methods.md, "Area lights: the light's half-vector
// region as a slope-space kernel"): delta lights keep the point form bit for bit, a tiny light is
// its point form, and for larger quad and sphere lights the half-vector kernel is closer to the
// reference that samples the light than the light as a point at its centre, without more flicker;
// no NaN under random lights crossing the horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "random_area_lights.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const std::map<std::string, std::string> kCentre = {{"light_extent", "centre"}};
const std::map<std::string, std::string> kKernel = {{"light_extent", "half-vector-kernel"}};

/// A glinty plane seen at an angle under one light ("quad", "sphere" or "point") of half size
/// `size` (quad: half its shorter side, the longer is twice; sphere: radius) at constant power, its
/// reflection in view; the camera turned by `degrees` about the vertical through the target.
TestScene glitter_under(const std::string& kind, double size, double degrees = 0.0) {
  const double t = degrees * 3.14159265358979 / 180.0;
  TestScene scene;
  scene.film(48, 32)
      .camera({3.0 * std::sin(t), 1.0, -1.0 + 4.0 * std::cos(t)}, {0.0, 0.1, -1.0}, 40)
      .glinty_material("glitter", {{"sigma", 0.1}, {"log_density", 16}, {"relative_area", 0.8}, {"f0", 0.9}})
      .plane("glitter", {{"size", 12}, {"uv_scale", 6}});
  const TomlValue position{0.0, 2.0, -2.5};
  if (kind == "quad")
    scene.light("quad", {{"position", position}, {"direction", {0.0, -2.0, 2.0}}, {"size", {4 * size, 2 * size}},
                         {"up", {0, 1, 0}}, {"radiance", 1.0 / (8 * size * size)}, {"visible", false}});
  else if (kind == "sphere")
    scene.sphere_light(position, size, 1.0 / (3.14159265358979 * size * size), {{"visible", false}});
  else
    scene.point_light(position, 1);
  return scene;
}

double mean_luminance(const Image& image) { return luminance(glm::vec3(image.mean())); }

}  // namespace

// Delta lights take the old code path: every choice renders the same image, bit for bit.
TEST(ChermainAreaLights, DeltaLightsKeepThePointForm) {
  SceneFixture f(glitter_under("point", 0.0));
  for (const std::string id : {"chermain2020", "chermain2021"}) {
    const Frame centre = f.method(id, kCentre), kernel = f.method(id, kKernel);
    EXPECT_GT(mean_luminance(centre.specular), 0.0) << id;
    EXPECT_EQ(rmse(centre.total, kernel.total), 0.0) << id;
  }
}

// As the light shrinks, its half-vector kernel vanishes (chermain2020) or tends to the pixel's
// kernel (chermain2021): a tiny light renders as its point form within float rounding, while a
// larger one differs (the test can fail).
TEST(ChermainAreaLights, ATinyLightIsItsPointForm) {
  for (const std::string kind : {"quad", "sphere"}) {
    SceneFixture tiny(glitter_under(kind, 1e-3)), larger(glitter_under(kind, 0.15));
    for (const std::string id : {"chermain2020", "chermain2021"}) {
      const Frame centre = tiny.method(id, kCentre);
      const double scale = mean_luminance(centre.specular);
      const double tiny_difference = rmse(centre.specular, tiny.method(id, kKernel).specular) / scale;
      const double larger_difference =
          rmse(larger.method(id, kCentre).specular, larger.method(id, kKernel).specular) / scale;
      std::printf("%s, %s: relative difference to the point form %.2e (tiny light), %.2e (half size 0.15)\n",
                  kind.c_str(), id.c_str(), tiny_difference, larger_difference);
      EXPECT_LT(tiny_difference, 2e-3) << kind << " " << id;
      EXPECT_GT(larger_difference, 50.0 * tiny_difference + 1e-2) << kind << " " << id;
    }
  }
}

// Larger lights against the reference that samples the light (MIS at every sub-pixel): the
// kernel's RMSE is lower than the centre's, and over a short camera turn its flicker (the
// frame-to-frame change of the error) is not higher.
TEST(ChermainAreaLights, TheKernelLowersTheErrorOfLargerLightsWithoutMoreFlicker) {
  for (const std::string kind : {"quad", "sphere"})
    for (double size : {0.15, 0.4}) {
      std::map<std::string, FlickerAccumulator> flicker;
      std::map<std::string, double> error;
      for (int frame = 0; frame < 3; ++frame) {
        SceneFixture f(glitter_under(kind, size, 1.0 * frame));
        const ReferenceFrame ref = f.reference_estimate(32, 0, frame);
        for (const std::string id : {"chermain2020", "chermain2021"})
          for (const auto& [choice, params] : {std::pair{"centre", kCentre}, std::pair{"kernel", kKernel}}) {
            const Frame m = f.method(id, params);
            error[id + " " + choice] += rmse(m.total, ref.mean.total) / 3.0;
            flicker[id + " " + choice].add_frame(m.total, ref.mean.total);
          }
      }
      for (const std::string id : {"chermain2020", "chermain2021"}) {
        const double e_centre = error[id + " centre"], e_kernel = error[id + " kernel"];
        const double f_centre = flicker[id + " centre"].flicker(), f_kernel = flicker[id + " kernel"].flicker();
        std::printf("%s %.2f, %s: RMSE centre %.4f kernel %.4f; flicker centre %.4f kernel %.4f\n", kind.c_str(), size,
                    id.c_str(), e_centre, e_kernel, f_centre, f_kernel);
        EXPECT_LT(e_kernel, e_centre) << kind << " " << size << " " << id;
        EXPECT_LE(f_kernel, f_centre) << kind << " " << size << " " << id;
      }
    }
}

// Random quad, disk and sphere lights of random size and orientation over a glinty plane and
// sphere, many crossing the sphere's horizon or lying almost in the plane: finite everywhere.
TEST(ChermainAreaLights, NoNanForRandomLightsCrossingTheHorizon) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    TestScene scene;
    scene.film(24, 16).camera({0.0, 1.0, 3.0}, {0.0, 0.2, -0.6}, 50);
    scene.glinty_material("glitter", {{"sigma", 0.02 + 0.2 * u01(rng)}, {"rho", 0.5}, {"log_density", 12 + 8 * u01(rng)}});
    scene.plane("glitter", {{"size", 12}}).sphere("glitter", {{"radius", 0.45}, {"translate", {0.0, 0.45, -0.4}}});
    add_random_area_lights(scene, rng, trial);
    SceneFixture f(scene);
    for (const std::string id : {"chermain2020", "chermain2021"}) {
      const Frame frame = f.method(id, kKernel);
      for (const Image* image : {&frame.total, &frame.specular})
        for (int y = 0; y < image->height(); ++y)
          for (int x = 0; x < image->width(); ++x) {
            const glm::vec3 p = image->at(x, y);
            ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && p.r >= 0.0f)
                << id << " trial " << trial << " pixel " << x << ", " << y;
          }
    }
  }
}
