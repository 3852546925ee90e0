// The environment light (src/scene/lights/environment.cpp, shaders/lights/environment.glsl) in
// images. White furnace: under a uniform environment of radiance 1 the reference gives a Lambert
// albedo of 1 exactly and a microfacet BRDF its directional albedo, computed here by the CPU's own
// quadrature (src/tables/dfg/dfg.hpp: a truth that shares no code with the GLSL sampler); every
// method's split sum stays within its stated error of it. A map with a small hot spot: every lobe
// method's glossy sphere against the reference. The background: what camera rays that miss see.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/image_io.hpp"
#include "gl_fixture.hpp"
#include "scratch_directory.hpp"
#include "core/metrics.hpp"
#include "shading/registry.hpp"
#include "tables/dfg/dfg.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 24;
/// The view's angle from the plane's normal: cos_o = cos(kViewDegrees) at every pixel.
constexpr double kViewDegrees = 50.0;

/// An orthographic view of the plane y = 0 from kViewDegrees off its normal: every pixel sees the
/// same cos_o, so that a furnace's pixels all equal one number.
TestScene tilted_plane(TomlKeys material, TomlKeys environment) {
  const double t = kViewDegrees * kPi / 180.0;
  return TestScene()
      .film(kSize, kSize)
      .orthographic_camera({0.0, 10.0 * std::cos(t), 10.0 * std::sin(t)}, {0, 0, 0}, 1.0, {{"near", 1}, {"far", 30}})
      .material("m", std::move(material))
      .plane("m", {{"size", 20}})
      .light("environment", std::move(environment));
}

double mean_green(const Image& image) { return image.mean().g; }

double diffuse_mean(const Frame& f) { return mean_green(f.total) - mean_green(f.specular); }

double max_deviation(const Image& image, double value) {
  double worst = 0.0;
  for (const glm::vec3& p : image.pixels()) worst = std::max(worst, std::abs(double(p.g) - value));
  return worst;
}
/// Pixels whose green differs from `value` by more than 6 standard errors (and 1e-4). The image is
/// uniform, so every pixel has the same error: pooled over the pixels, the reference's own
/// per-pixel estimates (from a few passes each) make one accurate standard error.
int pixels_off(const Image& image, const Image& standard_error, double value) {
  double variance = 0;
  for (const glm::vec3& e : standard_error.pixels()) variance += double(e.g) * e.g;
  const double sigma = std::sqrt(variance / double(standard_error.pixel_count()));
  int off = 0;
  for (const glm::vec3& p : image.pixels()) off += std::abs(p.g - value) > 6.0 * sigma + 1e-4;
  return off;
}

/// The methods that shade an environment with a lobe of their own (METHOD_SHADES_ENVIRONMENT).
const char* const kLobeMethods[] = {"conventional", "toksvig", "vlachos", "lean", "tokuyoshi",
                                    "kaplanyan-ggx", "kaplanyan-beckmann", "kaplanyan-rect"};

}  // namespace

TEST(EnvironmentLight, FurnaceReferenceLambertIsOne) {
  SceneFixture f(tilted_plane({{"diffuse", 1.0}, {"f0", 0.0}, {"alpha", 0.5}}, {{"radiance", 1.0}}));
  const ReferenceFrame ref = f.reference_estimate(16);
  EXPECT_NEAR(diffuse_mean(ref.mean), 1.0, 1e-3);
  Image diffuse = ref.mean.total;
  for (std::size_t i = 0; i < diffuse.pixel_count(); ++i) diffuse.pixels()[i] -= ref.mean.specular.pixels()[i];
  EXPECT_EQ(pixels_off(diffuse, ref.standard_error, 1.0), 0);
}

TEST(EnvironmentLight, FurnaceReferenceIsTheBrdfsDirectionalAlbedo) {
  const double cos_o = std::cos(kViewDegrees * kPi / 180.0);
  for (const auto& [ndf, kind] : {std::pair{"ggx", DfgNdf::Ggx}, std::pair{"beckmann", DfgNdf::Beckmann}})
    for (double alpha : {0.1, 0.4}) {
      SCOPED_TRACE(std::string(ndf) + " alpha " + std::to_string(alpha));
      SceneFixture f(tilted_plane({{"ndf", ndf}, {"alpha", alpha}, {"f0", 1.0}, {"diffuse", 0.0}}, {{"radiance", 1.0}}));
      const DfgTerms terms = dfg_terms(kind, cos_o, alpha);
      const double albedo = terms.a + terms.b;  // f0 = 1
      const ReferenceFrame ref = f.reference_estimate(16);
      EXPECT_NEAR(mean_green(ref.mean.specular), albedo, 1e-3);
      EXPECT_EQ(pixels_off(ref.mean.specular, ref.standard_error, albedo), 0);
    }
}

TEST(EnvironmentLight, FurnaceMirrorReflectsTheEnvironmentExactly) {
  SceneFixture f(tilted_plane({{"alpha", 0.0}, {"f0", 1.0}, {"diffuse", 0.0}}, {{"radiance", 1.0}}));
  EXPECT_LT(max_deviation(f.reference(4).specular, 1.0), 1e-6);
}

// One test for the two checks of the real-time methods: their programs are the same (one
// environment light, a plain microfacet material), so each is compiled once for both.
TEST(EnvironmentLight, MethodsInTheFurnaceAndLobeMethodsOnAHotSpot) {
  {
    // Uniform radiance: the prefiltered chain and the irradiance are exact, so what is left is
    // the DFG table's interpolation (docs/methods.md, "Environment lights": at most 5e-3 here).
    SCOPED_TRACE("furnace");
    const double cos_o = std::cos(kViewDegrees * kPi / 180.0);
    const double alpha = 0.3;
    const DfgTerms terms = dfg_terms(DfgNdf::Ggx, cos_o, alpha);
    const double specular = 0.5 * terms.a + terms.b;  // f0 = 0.5
    SceneFixture f(tilted_plane({{"alpha", alpha}, {"f0", 0.5}, {"diffuse", 0.5}}, {{"radiance", 1.0}}));
    for (const MethodDescriptor& m : all_methods()) {
      SCOPED_TRACE(m.id);
      const Frame frame = f.method(m.id);
      EXPECT_NEAR(mean_green(frame.specular), specular, 5e-3);
      EXPECT_NEAR(diffuse_mean(frame), 0.5, 1e-3);
    }
  }
  // A dim map with a small, bright hot spot where a glossy sphere reflects it towards the camera.
  SCOPED_TRACE("hot spot");
  ScratchDirectory scratch;
  Image map(64, 32, glm::vec3(0.05f));
  for (int y = 9; y < 11; ++y)
    for (int x = 30; x < 32; ++x) map.at(x, y) = glm::vec3(300.0f);  // 30 degrees up, turned behind the camera
  const auto file = scratch.path() / "hot-spot.exr";
  write_exr(file, {{"", &map}});
  SceneFixture f(TestScene()
                     .film(40, 40)
                     .camera({0.0, 0.0, 3.0}, {0, 0, 0}, 30)
                     .material("m", {{"alpha", 0.2}, {"f0", 0.9}, {"diffuse", 0.0}})
                     .sphere("m", {{"radius", 0.8}, {"segments", 48}})
                     .light("environment", {{"file", file.string()}, {"rotation", 180}, {"visible", false}}));
  const Frame ref = f.reference(16);
  const double reference_power = mean_green(ref.specular);
  ASSERT_GT(reference_power, 0.05);  // the hot spot is seen
  for (const char* id : kLobeMethods) {
    SCOPED_TRACE(id);
    const Frame frame = f.method(id);
    const double power = mean_green(frame.specular) / reference_power;
    const double error = rmse(frame.specular, ref.specular) / reference_power;
    std::printf("%-20s hot spot: power %.3f of the reference's, RMSE %.3f of its mean\n", id, power, error);
    EXPECT_NEAR(power, 1.0, 0.15);
    EXPECT_LT(error, 1.0);
  }
}

TEST(EnvironmentLight, CameraRaysThatMissSeeItOnlyWhenVisible) {
  for (bool visible : {true, false}) {
    SCOPED_TRACE(visible);
    SceneFixture f(TestScene()
                       .film(16, 16)
                       .camera({0.0, 0.0, 4.0}, {0, 0, 0}, 30)
                       .material("m", {{"diffuse", 0.5}, {"f0", 0.0}})
                       .sphere("m", {{"radius", 0.3}})
                       .light("environment", {{"radiance", {0.25, 0.5, 0.75}}, {"visible", visible}}));
    for (const Frame& frame : {f.method("conventional"), f.reference(4)}) {
      const glm::vec3 corner = frame.total.at(0, 0);
      EXPECT_NEAR(corner.r, visible ? 0.25 : 0.0, 1e-6);
      EXPECT_NEAR(corner.b, visible ? 0.75 : 0.0, 1e-6);
      EXPECT_EQ(frame.specular.at(0, 0).b, 0.0f);
    }
  }
}
