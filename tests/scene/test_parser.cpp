// The scene format: every class of bad input names the file, line or key, the value and what is
// allowed, and throws InputError (exit code 2 in the CLI).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"
#include "test_scenes.hpp"

using namespace glintlab;

namespace {

const std::string& kMinimal = test::kMinimalScene;

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "bad.toml", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, std::initializer_list<const char*> fragments) {
  const std::string msg = error_of(text);
  ASSERT_FALSE(msg.empty()) << "no error for:\n" << text;
  EXPECT_NE(msg.find("bad.toml"), std::string::npos) << msg;
  for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
}

}  // namespace

TEST(SceneParser, MinimalSceneGetsDocumentedDefaults) {
  const Scene s = parse_scene(kMinimal, "min.toml", ".");
  EXPECT_EQ(s.film.width, 640);
  EXPECT_EQ(s.film.height, 360);
  EXPECT_EQ(s.materials[0].ndf, Ndf::GGX);
  EXPECT_FLOAT_EQ(s.materials[0].alpha.x, 0.1f);
  EXPECT_EQ(s.shapes.size(), 1u);
  EXPECT_EQ(s.path.type, CameraPathType::Static);
}

TEST(SceneParser, EveryBuiltinSceneParsesAndHasACameraPath) {
  ASSERT_GE(builtin_scenes().size(), 4u);
  for (const auto& b : builtin_scenes()) {
    const Scene s = load_scene("builtin:" + b.name);
    EXPECT_GT(s.path.frames, 1) << b.name;
    EXPECT_NE(s.path.type, CameraPathType::Static) << b.name;
  }
  EXPECT_THROW(load_scene("builtin:nope"), InputError);
}

TEST(SceneParser, MalformedTomlNamesTheLine) { expect_error("[film\nwidth = 3", {"bad.toml:1", "malformed TOML"}); }

TEST(SceneParser, UnknownKeyIsRejected) {
  expect_error(kMinimal + "[film]\nwidht = 100\n", {"widht", "not a known key", "width"});
}

TEST(SceneParser, WrongTypeIsRejected) {
  expect_error(kMinimal + "[film]\nwidth = \"big\"\n", {"width", "\"big\"", "not an integer"});
}

TEST(SceneParser, OutOfRangeValueIsRejected) {
  expect_error(kMinimal + "[film]\nwidth = 0\n", {"width", "out of range", "1 .. 16384"});
  std::string alpha = kMinimal;
  alpha.replace(alpha.find("name = \"m\""), 10, "name = \"m\"\nalpha = 1.5");
  expect_error(alpha, {"alpha", "1.5", "0 .. 1"});
}

TEST(SceneParser, AbsurdFilmSizeIsRejected) {
  expect_error(kMinimal + "[film]\nwidth = 16000\nheight = 16000\n", {"64 Mpixels"});
}

TEST(SceneParser, UnknownEnumValueListsTheAllowedOnes) {
  expect_error(R"([[material]]
name = "m"
ndf = "phong"
)", {"ndf", "phong", "ggx, beckmann"});
}

TEST(SceneParser, UnknownMaterialReferenceListsTheDefinedOnes) {
  std::string t = kMinimal;
  t.replace(t.find("material = \"m\""), 14, "material = \"x\"");
  expect_error(t, {"\"x\"", "defined: m"});
}

TEST(SceneParser, MissingRequiredKeyAndEmptySceneAreRejected) {
  expect_error("[[light]]\ntype = \"point\"\n", {"position", "required"});
  expect_error("", {"no [[shape]]"});
}

TEST(SceneParser, TooManyLightsAreRejected) {
  std::string text = kMinimal;
  for (int i = 0; i < kMaxLights; ++i) text += "[[light]]\ntype = \"point\"\nposition = [0, 1, 0]\n";
  expect_error(text, {std::to_string(kMaxLights + 1).c_str(), "at most 128"});
}

TEST(SceneParser, MissingAndBrokenFilesAreNamed) {
  const auto dir = std::filesystem::temp_directory_path() / "glintlab-test-parser";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
  std::ofstream(dir / "broken.png") << "not a png";
  std::string mesh = kMinimal;
  mesh.replace(mesh.find("type = \"sphere\""), 15, "type = \"mesh\"\nfile = \"broken.obj\"");
  try {
    parse_scene(mesh, "m.toml", dir);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.obj"), std::string::npos) << e.what();
  }
  std::string nm = kMinimal;
  nm.replace(nm.find("name = \"m\""), 10, "name = \"m\"\nnormal_map = { file = \"broken.png\" }");
  try {
    parse_scene(nm, "m.toml", dir);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scene((dir / "missing.toml").string()), InputError);
  std::filesystem::remove_all(dir);
}

TEST(SceneParser, ObjMeshLoadsWithTangents) {
  const auto dir = std::filesystem::temp_directory_path() / "glintlab-test-obj";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                     "f 1/1 2/2 3/3 4/4\n";
  std::string t = kMinimal;
  t.replace(t.find("type = \"sphere\""), 15, "type = \"mesh\"\nfile = \"quad.obj\"");
  const Scene s = parse_scene(t, "m.toml", dir);
  ASSERT_EQ(s.shapes[0].mesh->triangle_count(), 2u);
  for (const auto& n : s.shapes[0].mesh->normals) EXPECT_NEAR(std::abs(n.y), 1.0f, 1e-5f);
  for (const auto& tg : s.shapes[0].mesh->tangents) EXPECT_NEAR(tg.x, 1.0f, 1e-5f);
  std::filesystem::remove_all(dir);
}

TEST(NormalMaps, BumpsHaveTheRequestedSlopeSpread) {
  const NormalMap m = generate_bumps(128, 0.3f, 64, 12, 5);
  double sx = 0, sy = 0;
  for (const auto& n : m.normals) {
    sx += (n.x / n.z) * (n.x / n.z);
    sy += (n.y / n.z) * (n.y / n.z);
  }
  // Slope variance over both axes = alpha^2 (Beckmann convention), within sampling error.
  EXPECT_NEAR((sx + sy) / static_cast<double>(m.normals.size()), 0.09, 0.01);
}
