// The environment light's map (src/scene/lights/environment_map.hpp): the lat-long convention the
// GLSL relies on, the loader's refusals (each naming the file) and the power-keeping downsampling.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "scene/lights/environment_map.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The integral of the radiance over the sphere, each texel weighted by its own solid angle.
glm::dvec3 power(const Image& map) {
  glm::dvec3 sum(0.0);
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) sum += environment_row_solid_angle(y, map.height()) * glm::dvec3(map.at(x, y));
  return sum;
}

Image random_map(int width, std::uint32_t seed) {
  Image map(width, width / 2);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(0.0f, 4.0f);
  for (auto& p : map.pixels()) p = glm::vec3(value(rng), value(rng), value(rng));
  return map;
}

/// Expects load_environment_map(file) to throw InputError whose message names the file and holds `detail`.
void expect_refused(const std::filesystem::path& file, const std::string& detail) {
  try {
    load_environment_map(file);
    ADD_FAILURE() << file << " was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
  }
}

}  // namespace

TEST(EnvironmentMap, TheConventionsAnchorDirections) {
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-6f; };
  EXPECT_TRUE(near(environment_direction(0.5, 0.5), {0, 0, -1}));  // the image centre
  EXPECT_TRUE(near(environment_direction(0.75, 0.5), {1, 0, 0}));
  EXPECT_TRUE(near(environment_direction(0.25, 0.5), {-1, 0, 0}));
  EXPECT_TRUE(near(environment_direction(0.0, 0.5), {0, 0, 1}));
  EXPECT_TRUE(near(environment_direction(1.0, 0.5), {0, 0, 1}));
  EXPECT_TRUE(near(environment_direction(0.3, 0.0), {0, 1, 0}));  // row 0 is the top: +y
  EXPECT_TRUE(near(environment_direction(0.3, 1.0), {0, -1, 0}));
  EXPECT_NEAR(environment_uv({0, 0, -1}).x, 0.5, 1e-12);
  EXPECT_NEAR(environment_uv({0, 0, -1}).y, 0.5, 1e-12);
  EXPECT_NEAR(environment_uv({1, 0, 0}).x, 0.75, 1e-12);
  EXPECT_NEAR(environment_uv({0, 1, 0}).y, 0.0, 1e-12);
  EXPECT_NEAR(environment_uv({0, -3, 0}).y, 1.0, 1e-12);
}

TEST(EnvironmentMap, DirectionsAndUvRoundTrip) {
  for (int i = 1; i < 40; ++i)
    for (int j = 1; j < 20; ++j) {
      const glm::dvec2 uv(i / 40.0, j / 20.0);
      const glm::dvec3 d = environment_direction_precise(uv.x, uv.y);
      EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
      const glm::dvec2 back = environment_uv(d);
      EXPECT_NEAR(back.x, uv.x, 1e-12) << uv.x << ", " << uv.y;
      EXPECT_NEAR(back.y, uv.y, 1e-12) << uv.x << ", " << uv.y;
      EXPECT_LT(glm::length(glm::dvec3(environment_direction(uv.x, uv.y)) - d), 1e-6);
    }
}

TEST(EnvironmentMap, TexelSolidAnglesTileTheSphere) {
  double total = 0;
  for (int y = 0; y < 16; ++y) total += 32 * environment_row_solid_angle(y, 16);
  EXPECT_NEAR(total, 4 * kPi, 1e-12);
}

TEST(EnvironmentMap, ReadsAValidMapAsIs) {
  test::ScratchDirectory dir;
  const Image map = random_map(64, 1);
  write_exr(dir / "sky.exr", {{"", &map}});
  const EnvironmentMap env = load_environment_map(dir / "sky.exr");
  EXPECT_EQ(env.source, (dir / "sky.exr").string());
  ASSERT_EQ(env.radiance.width(), 64);
  ASSERT_EQ(env.radiance.height(), 32);
  EXPECT_EQ(env.radiance.pixels(), map.pixels());
}

TEST(EnvironmentMap, RefusesEachBadFileNamingIt) {
  test::ScratchDirectory dir;
  expect_refused(dir / "missing.exr", "not found");

  const std::filesystem::path broken = dir / "broken.exr";
  { std::ofstream(broken) << "not an EXR file"; }
  expect_refused(broken, "cannot read");

  const Image square(32, 32, glm::vec3(1.0f));
  write_exr(dir / "square.exr", {{"", &square}});
  expect_refused(dir / "square.exr", "32 x 32, not 2:1; a lat-long map is twice as wide as it is high");

  const Image tiny(2, 1, glm::vec3(1.0f));
  write_exr(dir / "tiny.exr", {{"", &tiny}});
  expect_refused(dir / "tiny.exr", "2 x 1");

  Image with_nan(16, 8, glm::vec3(1.0f));
  with_nan.at(5, 3).g = std::numeric_limits<float>::quiet_NaN();
  write_exr(dir / "nan.exr", {{"", &with_nan}});
  expect_refused(dir / "nan.exr", "texel (5, 3)");

  Image with_inf(16, 8, glm::vec3(1.0f));
  with_inf.at(7, 2).b = std::numeric_limits<float>::infinity();
  write_exr(dir / "inf.exr", {{"", &with_inf}});
  expect_refused(dir / "inf.exr", "texel (7, 2) is (1, 1, inf), not finite");

  Image negative(16, 8, glm::vec3(1.0f));
  negative.at(9, 6).r = -0.5f;
  write_exr(dir / "negative.exr", {{"", &negative}});
  expect_refused(dir / "negative.exr", "texel (9, 6) is (-0.5, 1, 1), negative");
}

TEST(EnvironmentMap, AWideMapIsDownsampledByAPowerOfTwoKeepingItsPower) {
  test::ScratchDirectory dir;
  // 8 columns too wide: halved (not to 2048 exactly; the factor is a power of two).
  const Image map = random_map(kMaxEnvironmentWidth + 8, 2);
  write_exr(dir / "wide.exr", {{"", &map}});
  const EnvironmentMap env = load_environment_map(dir / "wide.exr");
  ASSERT_EQ(env.radiance.width(), (kMaxEnvironmentWidth + 8) / 2);
  ASSERT_EQ(env.radiance.height(), (kMaxEnvironmentWidth + 8) / 4);
  const glm::dvec3 before = power(map), after = power(env.radiance);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-5 * before[c]);
}

TEST(EnvironmentMap, DownsamplingKeepsThePowerForAnySizes) {
  const Image map = random_map(96, 3);
  for (int height : {24, 16, 12, 10, 7, 1}) {
    const Image small = downsample_environment(map, height);
    ASSERT_EQ(small.width(), 2 * height);
    const glm::dvec3 before = power(map), after = power(small);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-5 * before[c]) << height << " rows";
  }
  // Halving: each texel is the solid-angle-weighted mean of its 2 x 2 source texels.
  const Image half = downsample_environment(map, 24);
  const double w0 = environment_row_solid_angle(10, 48), w1 = environment_row_solid_angle(11, 48);
  const glm::dvec3 expected =
      (w0 * (glm::dvec3(map.at(6, 10)) + glm::dvec3(map.at(7, 10))) + w1 * (glm::dvec3(map.at(6, 11)) + glm::dvec3(map.at(7, 11)))) /
      (2 * (w0 + w1));
  EXPECT_LT(glm::length(glm::dvec3(half.at(3, 5)) - expected), 1e-5);
}

TEST(EnvironmentMap, UniformIsASmallConstantMap) {
  const EnvironmentMap env = uniform_environment_map({0.5f, 1.0f, 2.0f});
  EXPECT_EQ(env.source, "uniform");
  EXPECT_EQ(env.radiance.width(), 2 * env.radiance.height());
  for (const auto& p : env.radiance.pixels()) EXPECT_EQ(p, glm::vec3(0.5f, 1.0f, 2.0f));
}
