// The spot light (src/scene/lights/spot.cpp, shaders/lights/spot.glsl) in images: a spot whose
// cone is the hemisphere is the point light (bit for bit on Mesa); on a plane its irradiance follows
// KHR_lights_punctual's falloff at every pixel and is exactly 0 outside the outer cone, in every
// method; the reference (exact for delta lights) agrees with `conventional`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "gl_fixture.hpp"
#include "shading/registry.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 48;

/// The centre of pixel (px, py) of top_down_camera() on the plane y = 0.
glm::dvec3 pixel_centre(int px, int py) {
  return {-1.0 + (px + 0.5) * 2.0 / kSize, 0.0, -1.0 + (py + 0.5) * 2.0 / kSize};
}

/// A tilted spot over a 2 x 2 plane seen from above: the plane holds the full cone, the penumbra
/// and unlit corners.
struct Spot {
  glm::dvec3 position{0.2, 1.2, -0.1};
  glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
  double intensity = 3.0, inner = 15.0, outer = 35.0;

  TomlKeys keys() const {
    return {{"position", {position.x, position.y, position.z}},
            {"direction", {0.3, -1.0, 0.2}},
            {"intensity", intensity},
            {"inner_angle", inner},
            {"outer_angle", outer}};
  }
  /// cos of the angle between the axis and the direction from the light to q.
  double cos_to(const glm::dvec3& q) const { return glm::dot(axis, glm::normalize(q - position)); }
  /// KHR_lights_punctual's falloff: clamp((cd - cos outer) / (cos inner - cos outer), 0, 1)^2.
  double falloff(const glm::dvec3& q) const {
    const double ci = std::cos(inner * kPi / 180), co = std::cos(outer * kPi / 180);
    const double t = std::clamp((cos_to(q) - co) / std::max(0.001, ci - co), 0.0, 1.0);
    return t * t;
  }
  /// Irradiance on the plane y = 0 at q.
  double irradiance(const glm::dvec3& q) const {
    const glm::dvec3 d = position - q;
    return intensity * falloff(q) * (d.y / glm::length(d)) / glm::dot(d, d);
  }
  bool outside(const glm::dvec3& q, double margin) const {
    return std::acos(std::min(cos_to(q), 1.0)) > (outer + margin) * kPi / 180;
  }
};

/// A 2 x 2 plane seen from above under `light`, and one dark light (colour 0: it adds exactly 0)
/// of each other kind builtin:gltf-showcase has (a directional, a point and a spot light). The
/// light kinds and counts are then the showcase's, so every program drawn here (the plain default
/// material) is one that GltfMaterials' every-method test draws under the same lights, shared
/// through the GL driver's shader cache (tests/test_costs.cmake): a spot-only scene would make
/// llvmpipe build every method's program again, for the same code.
Scene plane_under(const std::string& material_name, TomlKeys material, const std::string& light,
                  TomlKeys light_keys) {
  TestScene scene = TestScene()
                        .top_down_camera()
                        .film(kSize, kSize)
                        .material(material_name, std::move(material))
                        .plane(material_name, {{"size", 2}})
                        .light(light, std::move(light_keys));
  if (light != "directional") scene.directional_light({0, -1, 0}, 1);
  if (light != "point") scene.point_light({0, 1, 0}, 1);
  if (light != "spot") scene.light("spot", {{"position", {0, 1, 0}}, {"direction", {0, -1, 0}}});
  Scene s = scene.scene();
  for (std::size_t i = 1; i < s.lights.size(); ++i) s.lights[i].colour = glm::vec3(0.0f);
  return s;
}

float diffuse_at(const Frame& f, int px, int py) { return f.total.at(px, py).g - f.specular.at(px, py).g; }

}  // namespace

TEST(SpotLight, HemisphereConeIsThePointLight) {
  // outer 90, inner 89.99: the transition is the spec's minimum, 0.001 in cos, so every point on
  // the plane (within 60 degrees of the axis here) gets a falloff of exactly 1, and the spot's
  // incidence is the point light's times 1.
  const TomlKeys material = {{"diffuse", 0.5}, {"f0", 0.5}, {"alpha", 0.3}};
  SceneFixture point(plane_under("m", material, "point", {{"position", {0.3, 1.0, 0.2}}, {"intensity", 2.0}}));
  SceneFixture spot(plane_under("m", material, "spot",
                                {{"position", {0.3, 1.0, 0.2}},
                                 {"direction", {0, -1, 0}},
                                 {"intensity", 2.0},
                                 {"inner_angle", 89.99},
                                 {"outer_angle", 90}}));
  auto expect_same = [](const Frame& a, const Frame& b, const std::string& what) {
    double worst = 0;
    int differing = 0;
    for (const auto& [x, y] : {std::pair{&a.total, &b.total}, std::pair{&a.specular, &b.specular}})
      for (std::size_t i = 0; i < x->pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
          const float p = x->pixels()[i][c], q = y->pixels()[i][c];
          differing += p != q;
          worst = std::max(worst, std::abs(double(p) - q) / std::max(std::abs(double(p)), 1e-30));
        }
    // Bit for bit on Mesa; a compiler that reassociates the products of the incidence (a GLSL
    // compiler may) leaves rounding: a few ulps.
    EXPECT_LE(worst, 4.0 / (1 << 23)) << what;
    std::printf("%s: %d values differ from the point light's, by %.2g at most\n", what.c_str(), differing, worst);
  };
  for (const std::string method : {"conventional", "podee", "kaplanyan-ggx"})
    expect_same(point.method(method), spot.method(method), method);
  const Frame a = point.reference(16);
  expect_same(a, spot.reference(16), "reference");
  EXPECT_GT(a.total.at(kSize / 2, kSize / 2).g, 0.0f);
}

TEST(SpotLight, IrradianceOnAPlaneFollowsTheFalloffAcrossTheConeEdge) {
  // A Lambert plane (albedo 0.5): the diffuse radiance at each pixel centre is 0.5 / pi times
  // the irradiance I falloff cos / d^2 - inside the inner cone, across the penumbra (where the
  // falloff is the square of the cosines' ramp) and outside the outer cone (exactly 0).
  const Spot spot;
  SceneFixture f(plane_under("white", {{"f0", 0}, {"diffuse", 0.5}, {"alpha", 0.5}}, "spot", spot.keys()));
  const Frame img = f.method("conventional");
  double peak = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) peak = std::max(peak, 0.5 / kPi * spot.irradiance(pixel_centre(px, py)));
  int full = 0, penumbra = 0, dark = 0;
  double worst = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const glm::dvec3 q = pixel_centre(px, py);
      const double expected = 0.5 / kPi * spot.irradiance(q), got = diffuse_at(img, px, py);
      const double falloff = spot.falloff(q);
      full += falloff == 1.0;
      penumbra += falloff > 0.0 && falloff < 1.0;
      if (spot.outside(q, 1e-3)) {
        ++dark;
        EXPECT_EQ(img.total.at(px, py), glm::vec3(0.0f)) << px << "," << py << " lies outside the outer cone";
      }
      worst = std::max(worst, std::abs(got - expected) / (1e-3 * expected + 1e-5 * peak));
    }
  EXPECT_LT(worst, 1.0) << "pixels off the formula by more than 0.1% (+ 1e-5 of the peak)";
  EXPECT_GT(full, 100);
  EXPECT_GT(penumbra, 300) << "pixels in the penumbra";
  EXPECT_GT(dark, 300) << "pixels outside the outer cone";
}

TEST(SpotLight, EveryMethodShadesTheDeltaSpotWithItsFalloff) {
  // Every method shades a delta light through deltaLightIncidence (podee's reflection space only
  // for disk forms): the diffuse part is conventional's everywhere and nothing outside the outer
  // cone is lit, specular included.
  const Spot spot;
  SceneFixture f(plane_under("metal", {{"f0", 0.8}, {"diffuse", 0.3}, {"alpha", 0.2}}, "spot", spot.keys()));
  const Frame conventional = f.method("conventional");
  for (const auto& method : all_methods()) {
    SCOPED_TRACE(method.id);
    const Frame img = f.method(method.id);
    double worst = 0, specular = 0;
    int lit_outside = 0;
    for (int py = 0; py < kSize; ++py)
      for (int px = 0; px < kSize; ++px) {
        const double a = diffuse_at(img, px, py), b = diffuse_at(conventional, px, py);
        worst = std::max(worst, std::abs(a - b) / (1e-4 * std::abs(b) + 1e-7));
        specular += img.specular.at(px, py).g;
        lit_outside += spot.outside(pixel_centre(px, py), 1e-3) && img.total.at(px, py) != glm::vec3(0.0f);
      }
    EXPECT_LT(worst, 1.0) << "diffuse differs from conventional's";
    EXPECT_EQ(lit_outside, 0) << "pixels lit outside the outer cone";
    EXPECT_GT(specular, 0.0);
  }
}

TEST(SpotLight, ReferenceAgreesWithConventionalForARoughMaterial) {
  // Both shade with the exact incidence of the delta light; they differ only in where in the pixel
  // they evaluate it (the reference averages 4 x 4 jittered sub-pixels, `conventional` takes the
  // centre), which is second order in the pixel size except at the cones' kinks: 3% of the peak
  // per pixel, 0.5% over the image, exactly 0 outside the outer cone in both.
  const Spot spot;
  SceneFixture f(plane_under("rough", {{"f0", 0.9}, {"diffuse", 0.2}, {"alpha", 0.4}}, "spot", spot.keys()));
  const Frame conv = f.method("conventional");
  const Frame ref = f.reference(16);
  double peak = 0, sum_conv = 0, sum_ref = 0, worst = 0;
  for (const glm::vec3& p : conv.total.pixels()) peak = std::max(peak, double(p.g));
  const double pixel_degrees = 2.0 / kSize / 1.2 * 180 / kPi;  // a pixel's size seen from the light, at most
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const double c = conv.total.at(px, py).g, r = ref.total.at(px, py).g;
      sum_conv += c;
      sum_ref += r;
      worst = std::max(worst, std::abs(c - r));
      if (spot.outside(pixel_centre(px, py), pixel_degrees)) {
        EXPECT_EQ(ref.total.at(px, py), glm::vec3(0.0f)) << px << "," << py;
      }
    }
  EXPECT_LT(worst, 0.03 * peak);
  EXPECT_NEAR(sum_ref / sum_conv, 1.0, 0.005);
  EXPECT_GT(peak, 0.0);
}
