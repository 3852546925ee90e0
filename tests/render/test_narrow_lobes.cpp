// Narrow lobes under lights with extent (issue 11, item 7): a mirror sphere under a small sun
// keeps its energy (closed form) with every footprint filter, and the shading of every lobe is
// continuous as the lobe narrows to a mirror (there is no mirror switch any more).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// Orthographic, so that the sphere's reflected directions cover the sphere of directions with
// the constant Jacobian 4 / R^2 and the highlight's energy does not depend on where it falls.
TestScene mirror_sphere_under_sun(double angular_radius) {
  return TestScene()
      .film(96, 96)
      .orthographic_camera({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, 2.2)
      .material("mirror", {{"alpha", 0.002}, {"f0", 1}, {"diffuse", 0}})
      .sphere("mirror", {{"radius", 1}, {"segments", 256}})
      .directional_light({-0.35, -0.45, -1.0}, 1, {{"angular_radius", angular_radius}});
}

/// Specular energy within 12 pixels of the mirror highlight (normal halfway between the viewer
/// and the sun) of an image whose camera moved by `shift` scene units: filters that widen lobes
/// towards the silhouette put light there that no mirror has, which is their own behaviour, not
/// the light's integral.
double highlight_energy(const Image& image, glm::dvec2 shift) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0, 0, 1) + glm::normalize(glm::dvec3(0.35, 0.45, 1.0)));
  const double pixel = 2.2 / 96, cx = 48 + (n.x - shift.x) / pixel, cy = 48 - (n.y - shift.y) / pixel;
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (std::pow(x + 0.5 - cx, 2) + std::pow(y + 0.5 - cy, 2) <= 144) sum += image.at(x, y).g;
  return sum;
}

}  // namespace

class MirrorSphereUnderSun : public ::testing::TestWithParam<double> {};

TEST_P(MirrorSphereUnderSun, CurvatureFiltersKeepTheEnergy) {
  // The truth in closed form: a mirror sphere (f0 = 1) seen orthographically reflects a sun of
  // angular radius g and radiance L = E / (pi sin^2 g) over an image of area pi R^2 (1 - cos g) / 2
  // (reflected directions have the Jacobian 4 / R^2), so its energy is L R^2 2 pi (1 - cos g) / 4.
  // Every curvature filter (vlachos, Kaplanyan's three, Tokuyoshi's) keeps it within 5% (measured:
  // within 1.2%); `conventional`, which filters nothing, point-samples the sub-pixel highlight and
  // misses by 27% and 7% at 0.25 and 0.5 degrees over the same 16 positions. The former shading kept 49-50% at 2 degrees (double
  // normalisation), and kaplanyan-ggx up to 149% (its lost box peak and the mirror path).
  // `toksvig` and `lean` filter normal maps only and equal `conventional` here.
  SceneFixture f(mirror_sphere_under_sun(GetParam()));
  const double g = GetParam() * M_PI / 180, pixel_area = std::pow(2.2 / 96, 2);
  const double truth = (1.0 / (M_PI * std::sin(g) * std::sin(g))) * 2 * M_PI * (1 - std::cos(g)) / 4 / pixel_area;
  // A method's energy is its expectation over where the highlight falls within a pixel: the mean
  // over a 4 x 4 grid of sub-pixel camera shifts (one frame alone is the method's flicker).
  constexpr int kShifts = 4;
  const Camera centred = f.scene.camera;
  for (const char* method : {"vlachos", "kaplanyan-beckmann", "kaplanyan-rect", "kaplanyan-ggx", "tokuyoshi"}) {
    double ratio = 0;
    for (int i = 0; i < kShifts * kShifts; ++i) {
      const glm::dvec2 shift = glm::dvec2((i % kShifts + 0.5) / kShifts, (i / kShifts + 0.5) / kShifts) * (2.2 / 96);
      f.scene.camera = centred;
      f.scene.camera.position += glm::vec3(glm::dvec3(shift, 0.0));
      f.scene.camera.target += glm::vec3(glm::dvec3(shift, 0.0));
      ratio += highlight_energy(f.method(method).specular, shift) / truth / (kShifts * kShifts);
    }
    f.scene.camera = centred;
    std::printf("sun %.2f deg: %s energy %.4f of the closed form\n", GetParam(), method, ratio);
    RecordProperty(std::string(method) + "_energy", std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.05) << method << " at " << GetParam() << " degrees";
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, MirrorSphereUnderSun, ::testing::Values(0.25, 0.5, 2.0), [](const auto& info) {
  return "Degrees" + std::to_string(static_cast<int>(std::lround(info.param * 100)));
});

TEST(NarrowLobes, ShadingIsContinuousAsTheLobeNarrows) {
  // shadeLobe for a sun of 0.5 degrees, at reflected directions inside, on the rim of and
  // outside the sun's disk, as the lobe's alpha sweeps 1e-4 .. 0.1 (GGX and Beckmann, matrix
  // and box lobes). A continuous function's largest step between neighbouring alphas halves when
  // the grid is refined twice over; a switch (the former mirror_alpha) keeps its step.
  const int coarse = 256;
  std::vector<glm::vec4> a, b;
  for (int refine : {1, 2})
    for (int kind = 0; kind < 4; ++kind)
      for (float offset : {0.0f, 0.8f, 1.0f, 1.3f})
        for (int i = 0; i <= coarse * refine; ++i) {
          const float alpha = std::pow(10.0f, -4.0f + 3.0f * float(i) / float(coarse * refine));
          a.emplace_back(alpha, offset, kind, refine);
          b.emplace_back(0.0f);
        }
  const auto gpu = evaluate_glsl("#include \"lobe/lobe_shading.glsl\"\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  float theta = radians(0.5);
  vec3 l = normalize(vec3(0.3, 0.0, 1.0));  // towards the sun
  // The viewer is placed so that the mirror direction is rotated from l by offset x theta.
  float tilt = a.y * theta;
  vec3 r = vec3(sin(atan(l.x, l.z) + tilt), 0.0, cos(atan(l.x, l.z) + tilt));
  Surface s;
  s.position = vec3(0.0);
  s.normal = vec3(0.0, 0.0, 1.0); s.tangent = vec3(1.0, 0.0, 0.0); s.bitangent = vec3(0.0, 1.0, 0.0);
  s.vertexNormal = s.normal;
  s.view = reflect(-r, s.normal);
  s.f0 = vec3(1.0); s.diffuse = vec3(0.0);
  LightData L;
  L.colour_type = vec4(1.0, 1.0, 1.0, float(LIGHT_SUN));
  L.direction_cos = vec4(-l, cos(theta));
  L.axis_u = vec4(0.0, 0.0, 0.0, 2.0 * sin(0.5 * theta) * sin(0.5 * theta));
  L.axis_v = vec4(0.0);
  L.position_radius = vec4(0.0);
  int kind = int(a.z);
  Lobe lobe = axisAlignedLobe(kind % 2, vec2(a.x, 0.7 * a.x));
  if (kind >= 2) lobe.footprint = vec2(0.5 * a.x, 0.3 * a.x);
  return vec4(shadeLobe(s, L, lobe).specular.g);
})",
                                 a, b);
  std::map<std::pair<int, float>, double> step[3];
  double radiance = 1.0 / (M_PI * std::pow(std::sin(0.5 * M_PI / 180), 2));
  for (std::size_t i = 1; i < a.size(); ++i) {
    if (a[i].w != a[i - 1].w || a[i].z != a[i - 1].z || a[i].y != a[i - 1].y) continue;
    const auto key = std::make_pair(int(a[i].z), a[i].y);
    double& s = step[int(a[i].w)][key];
    s = std::max(s, std::abs(double(gpu[i].x) - double(gpu[i - 1].x)) / radiance);
  }
  for (const auto& [key, coarse_step] : step[1]) {
    const double fine_step = step[2][key];
    EXPECT_LT(fine_step, 0.7 * coarse_step + 1e-4)
        << "lobe kind " << key.first << ", mirror direction at " << key.second << " sun radii: steps " << coarse_step
        << " -> " << fine_step;
    EXPECT_LT(coarse_step, 0.05) << "lobe kind " << key.first << " at " << key.second << " sun radii";
  }
}

// A surface seen edge-on with the sun behind the viewer reflects a small part of it: the
// representative point's first-order light image once covered a mirror-like lobe's peak at grazing
// half vectors, times (o.h) / (h.z o.z) ~ 1 / h.z^2 (up to 2.3e6 E). And kaplanyan-ggx keeps a
// sub-pixel highlight's energy wherever it falls in its pixel, as the box filter promises (the
// boxes of neighbouring pixels tile slope space): under LTC with the former Beckmann moment match
// it kept 59% to 212%.
namespace {

using Params = std::map<std::string, std::string>;
// The representative-point shadings a mirror-like lobe under a sun goes through: the baseline's
// option, and podee, whose smooth part is that shading.
const std::vector<std::pair<std::string, Params>> kRepresentativePointShadings = {
    {"conventional", {{"area_lights", "representative-point"}}}, {"podee", {}}};
// kaplanyan-ggx's two integrations of a light with extent (the representative point: the control).
const std::vector<std::pair<std::string, Params>> kAreaLightChoices = {
    {"ltc", {}}, {"representative-point", {{"area_lights", "representative-point"}}}};

}  // namespace

TEST(NarrowLobes, AGrazingViewSeesNoSunBehindTheViewer) {
  for (const double eps : {0.005, 0.01, 0.02})
    for (const double alpha : {0.0, 0.002, 0.03})
      for (const double degrees : {0.5, 2.0}) {
        SceneFixture f(TestScene()
                           .film(8, 8)
                           .orthographic_camera({0.0, 5 * std::sin(eps), 5 * std::cos(eps)}, {0.0, 0.0, 0.0}, 0.02)
                           .material("m", {{"alpha", alpha}, {"f0", 1}, {"diffuse", 0}})
                           .plane("m", {{"size", 4}})
                           .directional_light({0.0, -std::sin(eps), -std::cos(eps)}, 1, {{"angular_radius", degrees}}));
        for (const auto& [method, params] : kRepresentativePointShadings) {
          double worst = 0;
          const Image image = f.method(method, params).specular;
          for (const auto& p : image.pixels()) worst = std::max(worst, double(p.g));
          // E = 1: a surface seen edge-on with the sun behind the viewer reflects a small part of it.
          EXPECT_LT(worst, 1.0) << method << ": elevation " << eps << ", alpha " << alpha << ", sun " << degrees
                                << " deg: specular " << worst << " E";
        }
      }
  // Control: the sun at the mirror direction, a mirror: the sun's radiance, exactly.
  const double eps = 0.05, gamma = 2.0 * M_PI / 180.0;
  SceneFixture f(TestScene()
                     .film(8, 8)
                     .orthographic_camera({0.0, 5 * std::sin(eps), 5 * std::cos(eps)}, {0.0, 0.0, 0.0}, 0.02)
                     .material("m", {{"alpha", 0}, {"f0", 1}, {"diffuse", 0}})
                     .plane("m", {{"size", 4}})
                     .directional_light({0.0, -std::sin(eps), std::cos(eps)}, 1, {{"angular_radius", 2.0}}));
  const double radiance = 1.0 / (M_PI * std::sin(gamma) * std::sin(gamma));
  const Image mirror = f.method("conventional", {{"area_lights", "representative-point"}}).specular;
  for (std::size_t i = 0; i < mirror.pixel_count(); ++i) EXPECT_NEAR(mirror.pixels()[i].g / radiance, 1.0, 0.01) << "pixel " << i;
}

TEST(NarrowLobes, KaplanyanGgxKeepsASubPixelHighlightWhereverItFalls) {
  constexpr int kFilm = 64;
  constexpr double kViewHeight = 2.2;
  const double gamma = 0.25 * M_PI / 180.0, radius_px = kFilm / kViewHeight;
  const double truth = radius_px * radius_px / (4.0 * std::pow(std::cos(gamma / 2.0), 2));
  SceneFixture f(TestScene()
                     .film(kFilm, kFilm)
                     .orthographic_camera({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, kViewHeight)
                     .material("mirror", {{"alpha", 0}, {"f0", 1}, {"diffuse", 0}})
                     .sphere("mirror", {{"radius", 1}, {"segments", 256}})
                     .directional_light({0.0, 0.0, -1.0}, 1, {{"angular_radius", 0.25}}));
  const Camera centred = f.scene.camera;
  // The sphere's centre at a pixel corner (the film's centre), an edge's middle, a pixel centre
  // and in between.
  for (const auto& phase : {glm::dvec2(0, 0), glm::dvec2(0.5, 0), glm::dvec2(0.5, 0.5), glm::dvec2(0.25, 0.25)}) {
    const glm::dvec2 shift = phase * (kViewHeight / kFilm);
    f.scene.camera = centred;
    f.scene.camera.position += glm::vec3(glm::dvec3(shift, 0.0));
    f.scene.camera.target += glm::vec3(glm::dvec3(shift, 0.0));
    for (const auto& [name, params] : kAreaLightChoices) {
      double total = 0;
      const Image specular = f.method("kaplanyan-ggx", params).specular;
      for (const auto& p : specular.pixels()) total += p.g;
      EXPECT_NEAR(total / truth, 1.0, 0.03)
          << "kaplanyan-ggx (area_lights " << name << "), highlight at pixel phase (" << phase.x << ", " << phase.y
          << "): energy " << total / truth << " of the closed form";
    }
  }
  f.scene.camera = centred;
}
