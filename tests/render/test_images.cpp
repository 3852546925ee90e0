// Image tests that fail on a wrong implementation: closed forms, analytic coverage, convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/metrics.hpp"
#include "builtin_scene_programs.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

glm::dvec2 pixel_centre(int px, int py, int n) { return {-1.0 + (px + 0.5) * 2.0 / n, -1.0 + (py + 0.5) * 2.0 / n}; }

}  // namespace

TEST(Images, LambertPlaneUnderPointLightMatchesTheClosedForm) {
  SceneFixture f(TestScene()
                     .top_down_camera()
                     .film(32, 32)
                     .material("white", {{"f0", 0}, {"diffuse", 0.5}, {"alpha", 0.5}})
                     .plane("white", {{"size", 2}})
                     .point_light({0.3, 1.0, 0.2}, 2.0));
  const Frame img = f.method("conventional");
  double worst = 0;
  for (int py = 0; py < 32; ++py)
    for (int px = 0; px < 32; ++px) {
      const glm::dvec2 p = pixel_centre(px, py, 32);
      const glm::dvec3 d = glm::dvec3(0.3, 1.0, 0.2) - glm::dvec3(p.x, 0.0, p.y);
      const double expected = 0.5 / M_PI * 2.0 * (d.y / glm::length(d)) / glm::dot(d, d);
      const double diffuse = img.total.at(px, py).g - img.specular.at(px, py).g;
      worst = std::max(worst, std::abs(diffuse / expected - 1.0));
    }
  EXPECT_LT(worst, 0.01);
}

TEST(Images, GgxPlaneUnderDirectionalLightMatchesTheBrdfAtTheCentrePixel) {
  SceneFixture f(TestScene()
                     .film(33, 33)
                     .camera({0, 2, 2}, {0, 0, 0}, 30)
                     .material("metal", {{"alpha", 0.3}, {"f0", 0.9}})
                     .plane("metal", {{"size", 4}})
                     .directional_light({0.4, -1.0, 0.9}, 3.0));
  const Frame img = f.method("conventional");
  const glm::dvec3 v = glm::normalize(glm::dvec3(0, 2, 2)), l = -glm::normalize(glm::dvec3(0.4, -1.0, 0.9));
  const glm::dvec3 h = glm::normalize(v + l);
  const double a = 0.3;
  const double e = (h.x * h.x + h.z * h.z) / (a * a) + h.y * h.y;
  const double d = 1.0 / (M_PI * a * a * e * e);
  auto lambda = [&](glm::dvec3 w) { return 0.5 * (-1.0 + std::sqrt(1.0 + a * a * (1.0 - w.y * w.y) / (w.y * w.y))); };
  const double g = 1.0 / (1.0 + lambda(v) + lambda(l));
  const double fr = 0.9 + 0.1 * std::pow(1.0 - glm::dot(v, h), 5.0);
  const double expected = 3.0 * fr * d * g / (4.0 * v.y);  // f * cos(theta_l) * E
  EXPECT_NEAR(img.total.at(16, 16).r / expected, 1.0, 0.01) << "expected " << expected;
}

namespace {

/// Exact area of the disk (centre c, radius r) inside the axis-aligned square [x0,x1] x [z0,z1],
/// by integrating the clipped chord length along x (smooth integrand, fine midpoint rule).
double disk_square_area(glm::dvec2 c, double r, double x0, double x1, double z0, double z1) {
  const int steps = 4000;
  double area = 0;
  for (int i = 0; i < steps; ++i) {
    const double x = x0 + (i + 0.5) * (x1 - x0) / steps, dx = x - c.x;
    if (std::abs(dx) >= r) continue;
    const double half = std::sqrt(r * r - dx * dx);
    area += std::max(0.0, std::min(z1, c.y + half) - std::max(z0, c.y - half));
  }
  return area * (x1 - x0) / steps;
}

}  // namespace

TEST(Images, ReferenceCoverageOfAFlatMirrorUnderADiskLightIsAnalytic) {
  const int n = 24;
  SceneFixture f(TestScene()
                     .top_down_camera()
                     .film(24, 24)
                     .material("mirror", {{"alpha", 0}, {"f0", 1}})
                     .plane("mirror", {{"size", 2}})
                     .disk_light({0.1, 5, -0.05}, {0, -1, 0}, 0.53, 1, {{"visible", false}}));
  const glm::dvec2 centre(0.1, -0.05);
  const double r = 0.53, px_size = 2.0 / n;
  const Frame ref = f.reference(256);
  const Frame conv = f.method("conventional");
  double worst = 0, sum_ref = 0, sum_exact = 0;
  int edge_pixels = 0;
  for (int py = 0; py < n; ++py)
    for (int px = 0; px < n; ++px) {
      const glm::dvec2 p = pixel_centre(px, py, n);
      const double exact = disk_square_area(centre, r, p.x - px_size / 2, p.x + px_size / 2, p.y - px_size / 2,
                                            p.y + px_size / 2) / (px_size * px_size);
      const double got = ref.specular.at(px, py).r;
      worst = std::max(worst, std::abs(got - exact));
      sum_ref += got;
      sum_exact += exact;
      edge_pixels += exact > 0.0 && exact < 1.0;
      // The baseline sees the light through its (near-mirror) lobe at the pixel centre: the light's
      // radiance inside the disk, nothing outside, a continuous step within a pixel of the rim.
      const double rim = std::abs(glm::distance(p, centre) - r);
      const float c = conv.specular.at(px, py).r;
      if (rim > px_size) {
        EXPECT_NEAR(c, glm::distance(p, centre) < r ? 1.0f : 0.0f, 1e-3) << px << "," << py;
      }
      EXPECT_GE(c, 0.0f);
      EXPECT_LE(c, 1.0f + 1e-3f);
    }
  EXPECT_GT(edge_pixels, 20);
  EXPECT_LE(worst, 1.0 / 16.0 + 1e-3);              // at most one row of 16x16 sub-pixels off
  EXPECT_NEAR(sum_ref / sum_exact, 1.0, 0.005);      // covered area
}

TEST(Images, ReferenceConvergesWithMoreSamples) {
  SceneFixture f(builtin_scene("mirror-disk", 80, 45));
  // Independent seeds (frame 7) for the truth, so that its passes share nothing with the others'.
  const ReferenceFrame truth = f.reference_estimate(4096, 0, 7);
  double previous = 1e30;
  for (const int spp : {16, 64, 256, 1024}) {
    const ReferenceFrame r = f.reference_estimate(spp);
    const double error = rmse(r.mean.total, truth.mean.total);
    EXPECT_LT(error, previous) << spp << " spp";
    previous = error;
    // The reference's own error bars bound its actual error (from above: pass-to-pass spread
    // includes every source of noise), and are not vacuous.
    EXPECT_LT(error, 1.5 * std::hypot(r.noise_rmse(), truth.noise_rmse())) << spp << " spp";
    EXPECT_GT(error, 0.2 * std::hypot(r.noise_rmse(), truth.noise_rmse())) << spp << " spp";
  }
  EXPECT_EQ(truth.mean.total.count_non_finite(), 0u);
}

// One test per built-in scene, so that ctest runs them in parallel (most of their time is
// compiling each scene's program variants on llvmpipe). These renders are also the suite's compile
// check (by the driver) of every method's module and the reference's on each material kind a
// built-in scene has, with that scene's light kinds: Shaders.EveryMethodAndPassCompiles*
// (tests/glsl/test_shaders.cpp) validate the (module, variant, light kind) they leave out, read by
// builtin_scene_light_kinds() (tests/builtin_scene_programs.hpp). So render every method, at its
// defaults (but deng2022's precompute settings, below: its rank and grid specialise its programs,
// other constants in the same code; test_deng2022.cpp renders the defaults'), in every
// material of the scenes every_method_scenes() chooses (they hold every scene's material kinds),
// or change that helper to match; the other scenes render `conventional`.
// deng2022's pyramids of the normal-map-glints scenes' 256^2 maps at the default precompute
// settings take about 25 s of CPU each. Built smaller (rank 4, a stride of 16 texels at the finest
// level, 32^2 NDF images in 8^2 blocks: as many blocks a side as the defaults') they have the same
// structure (levels of halving footprints, groups, CP factors, prefix sums), are read by the same
// code and cover more pixels with the element fallback (yan2016's sum) below the first level: a
// NaN from either on these maps still shows. The defaults' pyramid is tested in test_deng2022.cpp.
const std::map<std::string, std::string> kSmallPyramid = {
    {"rank", "4"}, {"base_stride", "16"}, {"ndf_resolution", "32"}, {"block_size", "8"}};

class EveryMethodOnBuiltinScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethodOnBuiltinScene, IsFinite) {
  SceneFixture f(builtin_scene(GetParam(), 96, 54));
  const bool every_method = every_method_scenes().contains(GetParam());
  for (const auto& m : all_methods()) {
    if (!every_method && m.id != "conventional") continue;
    const Frame img = f.method(m.id, m.id == "deng2022" ? kSmallPyramid : std::map<std::string, std::string>{});
    EXPECT_EQ(img.total.count_non_finite(), 0u) << m.id << " on " << GetParam();
    EXPECT_GT(luminance(glm::vec3(img.total.mean())), 0.0f) << m.id << " on " << GetParam();
  }
  EXPECT_EQ(f.reference(4).total.count_non_finite(), 0u) << GetParam();
}

// The scenes every method renders on hold every material kind (textured or not) of the built-in
// scenes, in fewer scenes.
TEST(Images, EveryMethodScenesCoverEveryBuiltinScenesMaterialVariants) {
  std::set<std::pair<int, bool>> covered;
  for (const auto& name : every_method_scenes())
    for (const auto& p : builtin_scene_program_pairs().at(name)) covered.insert(kind_and_textures(p.first));
  for (const auto& [scene, pairs] : builtin_scene_program_pairs())
    for (const auto& p : pairs) EXPECT_TRUE(covered.contains(kind_and_textures(p.first))) << scene;
  EXPECT_LT(every_method_scenes().size(), builtin_scenes().size());
  std::string chosen;
  for (const auto& name : every_method_scenes()) chosen += " " + name;
  std::cout << "every method renders on:" << chosen << "\n";
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& b : builtin_scenes()) names.push_back(b.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Images, EveryMethodOnBuiltinScene, ::testing::ValuesIn(builtin_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });
