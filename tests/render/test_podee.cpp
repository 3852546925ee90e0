// Image tests of `podee` (micro-specular highlights): exactness on a flat mirror against the
// covered fraction computed on the CPU, energy of a sub-pixel highlight on a mirror sphere
// against the 1024-spp reference, and the glossy and sphere-light extensions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.hpp"
#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "sequence_metrics.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

double luminance_sum(const Image& image) {
  double sum = 0;
  for (const auto& p : image.pixels()) sum += luminance(p);
  return sum;
}

// A flat mirror (the plane y = 0, F = 1) seen from above, reflecting a tilted disk light.
const TestScene kFlatMirror = TestScene()
                                  .film(48, 36)
                                  .camera({0.0, 1.2, 3.0}, {0.0, 0.0, 0.0}, 40)
                                  .material("mirror", {{"alpha", 0}, {"f0", 1}, {"diffuse", 0}})
                                  .plane("mirror", {{"size", 20}})
                                  .disk_light({0.1, 1.5, -3.75}, {0.2, -0.45, 0.85}, 0.45, 1, {{"visible", false}});

/// Fraction of each pixel whose camera ray, reflected by the plane y = 0, hits the disk:
/// 64 x 64 sub-pixel rays in double precision, independent of the renderer's shading.
std::vector<double> covered_fraction(const Scene& scene) {
  const auto& cam = scene.camera;
  const int w = scene.film.width, h = scene.film.height;
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(cam.projection_matrix(float(w) / float(h)) * cam.view_matrix()));
  const auto& light = scene.lights.at(0);
  const glm::dvec3 c(light.position), n = glm::normalize(glm::dvec3(light.direction));
  const double radius = light.radius;
  const int k = 64;
  std::vector<double> fraction(static_cast<std::size_t>(w) * h, 0.0);
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      int hits = 0;
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const double x = 2.0 * (px + (i + 0.5) / k) / w - 1.0, y = 1.0 - 2.0 * (py + (j + 0.5) / k) / h;
          const glm::dvec4 a = inverse * glm::dvec4(x, y, -1, 1), b = inverse * glm::dvec4(x, y, 1, 1);
          const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::normalize(glm::dvec3(b) / b.w - o);
          if (d.y >= 0) continue;
          const glm::dvec3 p = o - d * (o.y / d.y);
          const glm::dvec3 r(d.x, -d.y, d.z);
          const double cosL = glm::dot(r, n);
          if (cosL >= 0) continue;
          const double t = glm::dot(c - p, n) / cosL;
          const glm::dvec3 q = p + t * r - c;
          hits += t > 0 && glm::dot(q, q) <= radius * radius;
        }
      fraction[static_cast<std::size_t>(py) * w + px] = double(hits) / (k * k);
    }
  return fraction;
}

struct EdgeError {
  double worst = 0;  // largest |method - fraction| over all pixels
  int edge_pixels = 0;
};

EdgeError compare_with_fraction(const Image& image, const std::vector<double>& fraction) {
  EdgeError e;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const double f = fraction[static_cast<std::size_t>(y) * image.width() + x];
      e.worst = std::max(e.worst, std::abs(double(image.at(x, y).g) - f));
      e.edge_pixels += f > 0.02 && f < 0.98;
    }
  return e;
}

}  // namespace

TEST(Podee, FlatMirrorUnderADiskGivesTheCoveredFraction) {
  // On a flat mirror the corner rays bound the pixel's reflected beam exactly, so every pixel,
  // including those that see only the light's rim, must show the covered fraction (F = 1, L = 1)
  // within 2%. Both ways of getting the corners; `conventional` and the paper's rays-from-the-
  // centre assumption are far off at the rim, which shows the test can fail.
  SceneFixture f(kFlatMirror);
  const auto fraction = covered_fraction(f.scene);
  for (const std::string corners : {"interpolated", "derivatives"}) {
    const auto e = compare_with_fraction(f.method("podee", {{"corners", corners}}).specular, fraction);
    EXPECT_GE(e.edge_pixels, 15) << corners;
    EXPECT_LT(e.worst, 0.02) << corners;
  }
  EXPECT_GT(compare_with_fraction(f.method("conventional").specular, fraction).worst, 0.3);
  EXPECT_GT(compare_with_fraction(f.method("podee", {{"origin", "centre"}}).specular, fraction).worst, 0.1);
}

namespace {

// One mirror sphere (F = 1) under a small disk (or sphere) light: its highlight is about 0.8
// pixel across, so conventional shading catches it in no pixel.
TestScene sphere_scene(double alpha, bool disk_light) {
  TestScene s = TestScene()
                    .film(64, 48)
                    .camera({0.0, 0.3, 4.0}, {0.0, 0.0, 0.0}, 30)
                    .material("m", {{"alpha", alpha}, {"f0", 1}, {"diffuse", 0}})
                    .sphere("m", {{"radius", 0.6}});
  return disk_light ? s.disk_light({2.0, 4.0, 3.0}, {-0.4, -0.8, -0.6}, 0.3, 100, {{"visible", false}})
                    : s.sphere_light({2.0, 4.0, 3.0}, 0.3, 100, {{"visible", false}});
}

}  // namespace

TEST(Podee, MirrorSphereKeepsTheHighlightsEnergy) {
  // A mirror sphere maps its image to reflected directions with a constant Jacobian, the
  // assumption behind the covered fraction: the highlight's energy must match the 1024-spp
  // reference within 5% with either way of getting the corners, where `conventional` misses it.
  SceneFixture f(sphere_scene(0, true));
  const Frame reference = f.reference(1024);
  const double reference_energy = luminance_sum(reference.specular);
  ASSERT_GT(reference_energy, 0.0);
  const double conventional_rmse = rmse(f.method("conventional").specular, reference.specular);
  for (const std::string corners : {"interpolated", "derivatives"}) {
    const Frame podee = f.method("podee", {{"corners", corners}});
    EXPECT_NEAR(luminance_sum(podee.specular) / reference_energy, 1.0, 0.05) << corners;
    EXPECT_LT(rmse(podee.specular, reference.specular), 0.05 * conventional_rmse) << corners;
  }
}

// Energy of `image` over the reference's tails (pixels between 1e-3 and 0.1 of its peak) over the
// reference's: the part of a glossy highlight that an equal-peak disk model leaves out.
double tail_energy_ratio(const Image& image, const Image& reference) {
  double peak = 0;
  for (const auto& p : reference.pixels()) peak = std::max(peak, double(luminance(p)));
  double method = 0, truth = 0;
  for (std::size_t i = 0; i < reference.pixels().size(); ++i) {
    const double r = luminance(reference.pixels()[i]);
    if (r < 1e-3 * peak || r >= 0.1 * peak) continue;
    method += luminance(image.pixels()[i]);
    truth += r;
  }
  return method / truth;
}

TEST(Podee, LobeExtensionHoldsOnAGlossySphereUnderASphereLight) {
  // GGX under a sphere light (the paper covers neither). alpha 0.03: the highlight is about a
  // pixel; the extension must beat `conventional` clearly and the paper's every-material-is-a-
  // mirror shading (glossy = off), keep the energy, and keep the lobe's tails (the equal-peak disk
  // alone put them into the core: 0.24 of the reference's there). alpha 0.1: the lobe's blur is
  // about as wide as the reflection space; podee must be at least as good as `conventional`
  // (formerly 2.2x its RMSE) and keep the tails (formerly 0.80).
  {
    SceneFixture f(sphere_scene(0.03, false));
    const Frame reference = f.reference(1024);
    const Frame podee = f.method("podee");
    const double extension = rmse(podee.specular, reference.specular);
    EXPECT_LT(extension, 0.6 * rmse(f.method("conventional").specular, reference.specular));
    EXPECT_LT(extension, rmse(f.method("podee", {{"glossy", "off"}}).specular, reference.specular));
    EXPECT_NEAR(luminance_sum(podee.specular) / luminance_sum(reference.specular), 1.0, 0.1);
    EXPECT_GT(tail_energy_ratio(podee.specular, reference.specular), 0.45);
  }
  {
    SceneFixture f(sphere_scene(0.1, false));
    const Frame reference = f.reference(1024);
    const Frame podee = f.method("podee");
    EXPECT_LE(rmse(podee.specular, reference.specular), rmse(f.method("conventional").specular, reference.specular));
    EXPECT_NEAR(tail_energy_ratio(podee.specular, reference.specular), 1.0, 0.15);
    EXPECT_NEAR(luminance_sum(podee.specular) / luminance_sum(reference.specular), 1.0, 0.05);
  }
}

TEST(Podee, EnumerationParametersTakeNamesOrIndices) {
  const auto& m = find_method("podee");
  EXPECT_EQ(resolve_params(m, {{"area", "lens"}}).at("area"), 2.0f);
  EXPECT_EQ(resolve_params(m, {{"area", "1"}}).at("area"), 1.0f);
  EXPECT_EQ(resolve_params(m, {}).at("glossy"), 1.0f);  // default "on"
  EXPECT_THROW(resolve_params(m, {{"area", "ellipse"}}), InputError);
  EXPECT_THROW(resolve_params(m, {{"corners", "0.5"}}), InputError);
}

TEST(Podee, BeatsConventionalOnTheNearMirrorScenes) {
  // The paper's claim (Table 1) on small versions of our two near-mirror scenes: lower RMSE and
  // flicker than `conventional` over 6 frames of the camera path (docs/results.md at full size).
  for (const std::string scene : {"mirror-disk", "mirror-bumps"}) {
    const auto measured = measure_sequence(scene, 6, {"conventional", "podee"});
    const Measured base = measured.at("conventional"), podee = measured.at("podee");
    EXPECT_LT(podee.rmse, base.rmse) << scene;
    EXPECT_LT(podee.flicker, base.flicker) << scene;
  }
}

TEST(Podee, CornersReadTheNormalMapAtTheBaseLevelByDefault) {
  // builtin:mirror-bumps at 160x90, near (frame 0) and far (frame 23): corners that read the map at
  // the pixel centre's mip level see the bumps flattened (docs/methods.md#podee, `corner_lod`); the
  // default (base level) must be clearly closer to the 256-spp reference than the centre's level.
  SceneFixture f(load_scene("builtin:mirror-bumps"));
  const int w = 160, h = 90;
  const auto& method = find_method("podee");
  EXPECT_EQ(resolve_params(method, {}).at("corner_lod"), -16.0f);
  for (const int t : {0, f.scene.path.frames - 1}) {
    const Camera camera = f.scene.path.at(f.scene.camera, t);
    ReferenceSettings settings;
    settings.spp = 256;
    const Frame reference = f.reference_at(camera, w, h, settings).mean;
    const auto error = [&](const std::map<std::string, std::string>& params) {
      return rmse(f.renderer->render(method, resolve_params(method, params), camera, w, h).total, reference.total);
    };
    const double base = error({}), centre = error({{"corner_lod", "0"}});
    EXPECT_LT(base, 0.7 * centre) << "frame " << t;
    const auto& conventional = find_method("conventional");
    EXPECT_LT(base, rmse(f.renderer->render(conventional, resolve_params(conventional, {}), camera, w, h).total,
                         reference.total))
        << "frame " << t;
  }
}

// A mirror sphere seen orthographically with a 2-degree sun straight behind the camera reflects
// the sun in a disk of radius R sin(1 deg) about its centre (0.5 px at 64x64) and nowhere else:
// its rim reflects the directions behind the sphere. podee once lit the rim three ways (the smooth
// part's light image covering the lobe's peak at grazing half vectors; corner rays all facing away
// from the light plane pushed to infinity around the light; corners extrapolated past the
// silhouette reflecting back towards the viewer): up to 1.7x the highlight's peak in one pixel.
namespace {

constexpr int kFilm = 64;
constexpr double kViewHeight = 2.2;

TestScene mirror_sphere_with_sun_behind_camera(double degrees) {
  return TestScene()
      .film(kFilm, kFilm)
      .orthographic_camera({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, kViewHeight)
      .material("mirror", {{"alpha", 0}, {"f0", 1}, {"diffuse", 0}})
      .sphere("mirror", {{"radius", 1}, {"segments", 256}})
      .directional_light({0.0, 0.0, -1.0}, 1, {{"angular_radius", degrees}});
}

}  // namespace

TEST(Podee, ASilhouetteSeesNoSunBehindTheViewer) {
  // The image's energy is E R^2 / (4 cos^2(gamma / 2)) (R in pixels; docs/results.md, "Ground
  // truth"), all of it within 0.5 px of the sphere's centre. Outside R/2 (normals more than 30
  // degrees from the view) nothing may be lit, for any sub-pixel position of the silhouette.
  const double gamma = 2.0 * M_PI / 180.0;
  const double radius_px = kFilm / kViewHeight;
  const double truth = radius_px * radius_px / (4.0 * std::pow(std::cos(gamma / 2.0), 2));
  SceneFixture f(mirror_sphere_with_sun_behind_camera(2.0));
  const Camera centred = f.scene.camera;
  for (const std::string corners : {"interpolated", "derivatives"}) {
    for (int k = 0; k < 8; ++k) {
      const double shift = k / 8.0 * kViewHeight / kFilm;  // scene units
      f.scene.camera = centred;
      f.scene.camera.position.x += static_cast<float>(shift);
      f.scene.camera.target.x += static_cast<float>(shift);
      const Image image = f.method("podee", {{"corners", corners}}).specular;
      double total = 0, rim = 0;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          const double v = image.at(x, y).g;  // F = 1, white: every channel alike
          total += v;
          const double dx = x + 0.5 - (kFilm / 2.0 - shift / (kViewHeight / kFilm)), dy = y + 0.5 - kFilm / 2.0;
          if (std::hypot(dx, dy) > 0.5 * radius_px) rim += v;
        }
      const std::string what = corners + " corners, camera shifted " + std::to_string(k) + "/8 px: energy " +
                               std::to_string(total / truth) + ", outside R/2 " + std::to_string(rim / truth);
      EXPECT_LT(rim, 1e-3 * truth) << what;
      EXPECT_NEAR(total / truth, 1.0, 0.02) << what;
    }
  }
  f.scene.camera = centred;
}
