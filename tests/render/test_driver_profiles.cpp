// The two driver profiles (docs/methods.md, "Driver profiles") change the shape of the code, not
// the physics: every method, and the reference, renders the same image in both, drawn here on
// llvmpipe. The scenes have two lights of one kind (the hardware profile's rolled loops run more
// than once), lights small and large against the lobes (kneiphof2024's cap and LTC sides; podee's
// reflection space and smooth shading) and each method's own material kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

/// A sphere of `kind` (on its own kinds a method runs its own code) under a point light, a small
/// and a large sphere light and a quad.
Scene profile_scene(const std::string& kind) {
  TomlKeys material{{"alpha", 0.12}, {"f0", 0.9}, {"diffuse", 0.1}};
  if (kind == "microfacet") {
    material.push_back({"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.2}, {"seed", 3}}});
  } else if (kind == "glinty") {
    material = {{"type", "glinty"}, {"sigma", 0.2}, {"log_density", 12}};
  } else if (kind == "binomial-glints") {
    material = {{"type", "binomial-glints"}, {"alpha", 0.2}, {"log_density", 12}, {"microfacet_roughness", 0.02}};
  } else if (kind == "normal-map-glints") {
    material = {{"type", "normal-map-glints"},
                {"intrinsic_roughness", 0.02},
                {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.25}, {"seed", 5}}}};
  }
  TestScene s;
  s.film(20, 16)
      .camera({0, 0.5, 2.4}, {0, 0, 0}, 40)
      .material("m", material)
      .sphere("m")
      .point_light({1.5, 2, 2}, 4)
      .sphere_light({-1.5, 1.2, 1.5}, 0.02, 3000)  // small against every lobe here: the cap
      .sphere_light({1.4, 0.6, 1.6}, 0.7, 2)       // large: the LTC
      .light("quad", {{"position", {0, 2.5, 0.5}}, {"direction", {0, -1, -0.2}}, {"size", {1.5, 0.3}}, {"radiance", 4}});
  return s.scene();
}

/// The largest difference between two images, relative to max(1, the first's value).
double largest_relative_difference(const Image& a, const Image& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = a.pixels()[i][c], y = b.pixels()[i][c];
      worst = std::max(worst, std::abs(x - y) / std::max(1.0, std::abs(x)));
    }
  return worst;
}

/// A scene drawn by both profiles' renderers (the test's library is the software profile's on llvmpipe).
struct TwoProfiles {
  explicit TwoProfiles(const std::string& kind) : fixture(profile_scene(kind)) {
    EXPECT_EQ(shaders().driver_profile(), DriverProfile::Software) << "llvmpipe's profile";
    add_contract_sources(hardware_shaders);
    hardware = std::make_unique<Renderer>(hardware_shaders, *fixture.gpu);
  }
  SceneFixture fixture;
  ShaderLibrary hardware_shaders{DriverProfile::Hardware};
  std::unique_ptr<Renderer> hardware;
};

}  // namespace

TEST(DriverProfiles, EveryMethodAndTheReferenceRenderTheSameImageInBoth) {
  std::map<std::string, std::unique_ptr<TwoProfiles>> scenes;
  const auto scene = [&](const std::string& kind) -> TwoProfiles& {
    auto& s = scenes[kind];
    if (!s) s = std::make_unique<TwoProfiles>(kind);
    return *s;
  };
  for (const MethodDescriptor& m : all_methods()) {
    const std::vector<std::string> kinds = m.material_kinds.empty() ? std::vector<std::string>{"microfacet"} : m.material_kinds;
    for (const std::string& kind : kinds) {
      TwoProfiles& t = scene(kind);
      const Scene& sc = t.fixture.scene;
      const ParamValues params = resolve_params(m, {});
      const Frame software = t.fixture.renderer->render(m, params, sc.camera, sc.film.width, sc.film.height);
      const Frame hardware = t.hardware->render(m, params, sc.camera, sc.film.width, sc.film.height);
      ASSERT_EQ(software.total.count_non_finite(), 0u) << m.id;
      EXPECT_GT(software.specular.mean().x, 0.0) << m.id << " on " << kind << ": the scene lights the sphere";
      EXPECT_LE(largest_relative_difference(software.total, hardware.total), 1e-5) << m.id << " on " << kind;
      EXPECT_LE(largest_relative_difference(software.specular, hardware.specular), 1e-5) << m.id << " on " << kind;
    }
  }
  // The reference: the same jittered samples (the frame's seed) through either profile's program.
  TwoProfiles& t = scene("microfacet");
  ReferenceSettings settings;
  settings.spp = 16;
  const auto hardware_backend = make_reference_backend("raster", {t.hardware_shaders, *t.fixture.gpu, *t.hardware});
  const Scene& sc = t.fixture.scene;
  const ReferenceFrame software = t.fixture.reference_at(sc.camera, sc.film.width, sc.film.height, settings);
  const ReferenceFrame hardware = render_reference(*hardware_backend, sc.camera, sc.film.width, sc.film.height, settings);
  EXPECT_LE(largest_relative_difference(software.mean.total, hardware.mean.total), 1e-5);
}
