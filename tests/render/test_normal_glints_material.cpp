// The normal-map-glints material's ground truth (docs/scene-format.md#normal-map-glints-materials):
// the reference evaluates the contract's BRDF at each sample point of the map, against C++ written
// here from the contract alone: a constant tilted map under a delta light (closed form), a bumpy map
// seen from afar (the map's average of the BRDF, by quadrature over the bilinear field), a constant
// map under a sun with extent (quadrature over the sun: the BRDF sampling's density under MIS), and
// no NaN under random lights. Tiny images and maps: every case takes well under a second.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "gl_fixture.hpp"
#include "random_area_lights.hpp"
#include "scene/materials/normal_glints.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kF0 = 0.9;

// Beckmann's Smith Lambda by Walter et al. 2007's rational fit (the function docs/scene-format.md
// names), in a = 1 / (alpha tan theta).
double beckmann_lambda(glm::dvec3 w, double alpha) {
  const double sin_t = std::sqrt(w.x * w.x + w.y * w.y);
  if (sin_t <= 0) return 0;
  const double a = w.z / (alpha * sin_t);
  return a >= 1.6 ? 0.0 : (1 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
}

// A microfacet BRDF times wi.z, macro frame: F(wo.h) G2(masking alpha) D / (4 wo.z), D = ndf(h).
template <typename Ndf>
double specular_cos(glm::dvec3 wo, glm::dvec3 wi, double masking_alpha, Ndf ndf) {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double f = kF0 + (1 - kF0) * std::pow(1 - glm::dot(wo, h), 5);
  const double g2 = 1 / (1 + beckmann_lambda(wo, masking_alpha) + beckmann_lambda(wi, masking_alpha));
  return f * g2 * ndf(h) / (4 * wo.z);
}

// The contract's: D(h) = P(h.xy), P = N2(mean, sigma^2 I) the density of the projected normal over
// the plane (ds = h.z dw_h, so that integral D h.z dw = 1).
double contract_specular_cos(glm::dvec3 wo, glm::dvec3 wi, glm::dvec2 mean, double sigma, double masking_alpha) {
  return specular_cos(wo, wi, masking_alpha, [&](glm::dvec3 h) {
    const glm::dvec2 d = glm::dvec2(h) - mean;
    return std::exp(-0.5 * glm::dot(d, d) / (sigma * sigma)) / (2 * M_PI * sigma * sigma);
  });
}

// Smooth Beckmann of alpha (Walter et al. 2007, eq. 25) with the same masking.
double beckmann_specular_cos(glm::dvec3 wo, glm::dvec3 wi, double alpha) {
  return specular_cos(wo, wi, alpha, [&](glm::dvec3 h) {
    const double tan2 = (h.x * h.x + h.y * h.y) / (h.z * h.z);
    return std::exp(-tan2 / (alpha * alpha)) / (M_PI * alpha * alpha * std::pow(h.z, 4));
  });
}

// The plane's macro frame (src/scene/mesh.cpp: u along +x, v along -z, normal +y): local <-> world.
glm::dvec3 plane_to_world(glm::dvec3 w) { return {w.x, w.z, -w.y}; }

// Straight down onto a plane of one normal-map-glints material, no diffuse: the view is the square
// [-1, 1]^2 of a plane twice as wide, uv 0.5 per metre, so that a tiling of 2 puts 2 x 2 tiles in view.
TestScene top_down_plane(int film, double sigma, TomlKeys normal_map, double tiling) {
  TestScene s;
  s.film(film, film).top_down_camera();
  s.material("metal", {{"type", "normal-map-glints"}, {"intrinsic_roughness", sigma}, {"f0", kF0},
                       {"normal_map", std::move(normal_map)}, {"normal_map_tiling", tiling}});
  s.plane("metal", {{"size", 4}, {"uv_scale", 2}});
  return s;
}

// The scene with its map replaced by a constant one of normal n (and its masking alpha).
Scene with_constant_map(Scene scene, glm::dvec3 n) {
  auto map = std::make_shared<NormalMap>();
  map->width = map->height = 4;
  map->normals.assign(16, glm::vec3(glm::normalize(n)));
  map->description = "constant";
  Material& m = scene.materials[0];
  m.normal_map = map;
  m.set_kind_param("masking_alpha", normal_glint_masking_alpha(*map, m.kind_param("intrinsic_roughness")));
  return scene;
}

double mean_green(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).g;
  return sum / (image.width() * image.height());
}

const glm::dvec3 kTilt = glm::normalize(glm::dvec3(0.25, -0.15, 1.0));  // a tilted, constant map normal
constexpr double kSigma = 0.05;

}  // namespace

// A constant map tilted in both axes, a directional light: every pixel is the closed form, to float
// precision. It fails if the map's x or y is read with another sign than the vertex frame's (the
// mean would move by 0.5 or 0.3, ten and six sigma), if the NDF or the masking lived in the mapped
// normal's frame, or if D were P / h.z (5% more here: h.z = 0.952).
TEST(NormalGlintsReference, ConstantTiltedMapIsTheClosedFormUnderADeltaLight) {
  const glm::dvec3 wo(0, 0, 1);  // the top-down camera's view, in the plane's frame
  // A half vector off the map's normal by (0.8, 0.4) sigma, and the light it reflects.
  const glm::dvec2 s = glm::dvec2(kTilt) + glm::dvec2(0.8, 0.4) * kSigma;
  const glm::dvec3 h(s, std::sqrt(1 - glm::dot(s, s)));
  const glm::dvec3 wi = 2 * glm::dot(wo, h) * h - wo;
  TestScene ts = top_down_plane(8, kSigma, TomlKeys{{"generator", "bumps"}, {"resolution", 4}, {"alpha", 0.0}}, 1);
  const glm::dvec3 travel = -plane_to_world(wi);
  ts.directional_light({travel.x, travel.y, travel.z}, 1.0);
  SceneFixture f(with_constant_map(ts.scene(), kTilt));
  const double masking = f.scene.materials[0].kind_param("masking_alpha");
  EXPECT_NEAR(masking, std::sqrt(std::pow(glm::length(glm::dvec2(kTilt)) / kTilt.z, 2) + 2 * kSigma * kSigma), 1e-6);
  const double truth = contract_specular_cos(wo, wi, glm::dvec2(kTilt), kSigma, masking);
  const Image image = f.reference(4).specular;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) ASSERT_NEAR(image.at(x, y).g / truth, 1.0, 2e-3) << x << ", " << y;
  std::printf("constant tilted map: reference %.5f, closed form %.5f (P / h.z would give %.5f)\n",
              image.at(3, 3).g, truth, truth / h.z);
}

// A bumpy map with 2 x 2 texels per pixel, seen straight down under a directional light: the
// image's mean is the map's average of the BRDF over the bilinear normal field, by a fine
// quadrature here (8 x 8 points a texel). It fails if the reference reads a filtered level
// (averaged normals are smoother: their average BRDF differs by far more than the tolerance) or
// the map through another tiling. The smooth Beckmann of the masking alpha (what every other
// method shades in this limit) is near it: the limit only approximately.
TEST(NormalGlintsReference, BumpyMapFromAfarIsTheMapsAverageOfTheBrdf) {
  constexpr int kRes = 32;
  constexpr double kTiling = 2.0, kSigmaR = 0.04;
  const glm::dvec3 wo(0, 0, 1);
  const glm::dvec3 wi = glm::normalize(glm::dvec3(0.45, 0.3, 1.0));
  TestScene ts = top_down_plane(32, kSigmaR,
                                TomlKeys{{"generator", "bumps"}, {"resolution", kRes}, {"alpha", 0.3}, {"waves", 48},
                                         {"max_frequency", 6}, {"seed", 3}},
                                kTiling);
  const glm::dvec3 travel = -plane_to_world(wi);
  ts.directional_light({travel.x, travel.y, travel.z}, 1.0);
  SceneFixture f(ts);
  const Material& m = f.scene.materials[0];
  const NormalMap& map = *m.normal_map;
  // n(u): bilinear between texel centres ((i + 0.5) / W), wrapping, then normalised.
  auto texel = [&](int i, int j) {
    return glm::dvec3(map.normals[static_cast<std::size_t>(((j % kRes) + kRes) % kRes) * kRes + ((i % kRes) + kRes) % kRes]);
  };
  constexpr int kSub = 8;
  double sum = 0;
  for (int j = 0; j < kRes * kSub; ++j)
    for (int i = 0; i < kRes * kSub; ++i) {
      const double x = (i + 0.5) / kSub - 0.5, y = (j + 0.5) / kSub - 0.5;  // texel-centre coordinates
      const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
      const double a = x - i0, b = y - j0;
      const glm::dvec3 n = glm::normalize((1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0 + 1, j0) +
                                          (1 - a) * b * texel(i0, j0 + 1) + a * b * texel(i0 + 1, j0 + 1));
      sum += contract_specular_cos(wo, wi, glm::dvec2(n), kSigmaR, m.kind_param("masking_alpha"));
    }
  const double truth = sum / (kRes * kSub * kRes * kSub);
  const ReferenceFrame reference = f.reference_estimate(1024);
  const double mean = mean_green(reference.mean.specular), noise = reference.relative_energy_error(true);
  const double alpha = m.kind_param("masking_alpha");
  const double smooth = beckmann_specular_cos(wo, wi, alpha);
  std::printf("bumpy map from afar: reference mean %.5f (relative error %.4f), map average %.5f, smooth Beckmann(%.4f) %.5f\n",
              mean, noise, truth, alpha, smooth);
  EXPECT_NEAR(mean / truth, 1.0, std::max(0.005, 4 * noise));  // measured: 0.03%, noise 0.02%
  // The smooth limit is only approximate (the map's slopes are not exactly Beckmann, and sigma_r
  // adds in projected normals, not slopes): measured 2.6% above the map's average.
  EXPECT_NEAR(smooth / truth, 1.0, 0.05);
}

// A constant tilted map under a sun 3 degrees wide (about the lobe's width): the reference's MIS of
// light and BRDF samples against quadrature of the contract's BRDF over the sun's disk. A wrong
// density of the BRDF samples (a Jacobian missing or extra) biases MIS's result.
TEST(NormalGlintsReference, ConstantMapUnderASunIsTheQuadratureOverTheSun) {
  const glm::dvec3 wo(0, 0, 1);
  const glm::dvec2 s = glm::dvec2(kTilt) + glm::dvec2(0.5, -0.3) * kSigma;
  const glm::dvec3 h(s, std::sqrt(1 - glm::dot(s, s)));
  const glm::dvec3 axis = 2 * glm::dot(wo, h) * h - wo;  // towards the sun's centre, plane frame
  constexpr double kRadiusDegrees = 3.0, kIrradiance = 1.0;
  TestScene ts = top_down_plane(8, kSigma, TomlKeys{{"generator", "bumps"}, {"resolution", 4}, {"alpha", 0.0}}, 1);
  const glm::dvec3 travel = -plane_to_world(axis);
  ts.light("sun", {{"direction", {travel.x, travel.y, travel.z}}, {"irradiance", kIrradiance},
                   {"angular_radius", kRadiusDegrees}});
  SceneFixture f(with_constant_map(ts.scene(), kTilt));
  const double masking = f.scene.materials[0].kind_param("masking_alpha");
  // Quadrature over the cone (midpoints in cos theta and phi about the axis).
  const double g = kRadiusDegrees * M_PI / 180, radiance = kIrradiance / (M_PI * std::sin(g) * std::sin(g));
  const glm::dvec3 t1 = glm::normalize(glm::cross(axis, glm::dvec3(0, 1, 0))), t2 = glm::cross(axis, t1);
  constexpr int kN = 400;
  double sum = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const double c = 1 - (1 - std::cos(g)) * (i + 0.5) / kN, sn = std::sqrt(1 - c * c), phi = 2 * M_PI * (j + 0.5) / kN;
      const glm::dvec3 wi = c * axis + sn * (std::cos(phi) * t1 + std::sin(phi) * t2);
      sum += contract_specular_cos(wo, wi, glm::dvec2(kTilt), kSigma, masking);
    }
  const double truth = sum * radiance * 2 * M_PI * (1 - std::cos(g)) / (kN * kN);
  const ReferenceFrame reference = f.reference_estimate(64, 16);
  const double mean = mean_green(reference.mean.specular), noise = reference.relative_energy_error(true);
  std::printf("constant map under a %.0f-degree sun: reference %.5f (relative error %.4f), quadrature %.5f\n",
              kRadiusDegrees, mean, noise, truth);
  EXPECT_NEAR(mean / truth, 1.0, std::max(0.01, 4 * noise));
}

// Random quads, disks and spheres crossing the horizon over a bumpy normal-map-glints plane and
// sphere: the reference is finite and non-negative everywhere (every method on this material:
// Images/EveryMethodOnBuiltinScene.IsFinite/normal_glints_noise).
TEST(NormalGlintsReference, NoNanForRandomLightsCrossingTheHorizon) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    TestScene scene;
    scene.film(24, 16).camera({0.0, 1.0, 3.0}, {0.0, 0.2, -0.6}, 50);
    scene.material("bumpy", {{"type", "normal-map-glints"},
                             {"intrinsic_roughness", 0.001 + 0.05 * u01(rng)},
                             {"f0", 0.9},
                             {"diffuse", 0.1},
                             {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 16}, {"alpha", 0.6},
                                                     {"max_frequency", 4}, {"seed", trial}}},
                             {"normal_map_tiling", 8}});
    scene.plane("bumpy", {{"size", 12}}).sphere("bumpy", {{"radius", 0.45}, {"translate", {0.0, 0.45, -0.4}}});
    add_random_area_lights(scene, rng, trial);
    scene.point_light({0.3, 1.5, 0.5}, 2.0);
    SceneFixture f(scene);
    const Frame frame = f.reference(4, 4);
    for (const Image* image : {&frame.total, &frame.specular})
      for (int y = 0; y < image->height(); ++y)
        for (int x = 0; x < image->width(); ++x) {
          const glm::vec3 p = image->at(x, y);
          ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && p.r >= 0.0f)
              << "trial " << trial << " pixel " << x << ", " << y;
        }
  }
}
