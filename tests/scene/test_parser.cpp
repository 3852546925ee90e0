// The scene format: every class of bad input names the file, line or key, the value and what is
// allowed, and throws InputError (exit code 2 in the CLI).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"
#include "scratch_directory.hpp"
#include "test_scenes.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

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
  const Scene s = TestScene::minimal().scene();
  EXPECT_EQ(s.film.width, 640);
  EXPECT_EQ(s.film.height, 360);
  EXPECT_EQ(s.materials[0].ndf, Ndf::GGX);
  EXPECT_FLOAT_EQ(s.materials[0].alpha.x, 0.1f);
  EXPECT_EQ(s.shapes.size(), 1u);
  EXPECT_EQ(s.path.type, CameraPathType::Static);
}

TEST(SceneParser, EveryBuiltinSceneIsItsFileAndHasACameraPath) {
  // builtin:NAME is scenes/NAME.toml as built in, and loading the file by path gives the same
  // scene: a user's copy needs nothing else (no file it refers to, no generated part).
  std::set<std::string> files, builtins;
  for (const auto& e : std::filesystem::directory_iterator(GLINTLAB_SCENES_DIR))
    if (e.path().extension() == ".toml") files.insert(e.path().stem().string());
  for (const auto& b : builtin_scenes()) {
    builtins.insert(b.name);
    const Scene s = load_scene("builtin:" + b.name);
    EXPECT_GT(s.path.frames, 1) << b.name;
    EXPECT_NE(s.path.type, CameraPathType::Static) << b.name;
    EXPECT_FALSE(b.description.empty()) << b.name;
    EXPECT_EQ(s.description, b.description) << b.name;
    const auto path = std::filesystem::path(GLINTLAB_SCENES_DIR) / (b.name + ".toml");
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(builtin_scene_toml(b.name), text) << b.name << ": rebuild to embed the edited file";
    EXPECT_EQ(load_scene(path.string()).content_hash(), s.content_hash()) << b.name;
  }
  EXPECT_EQ(files, builtins);
  EXPECT_THROW(load_scene("builtin:nope"), InputError);
}

TEST(SceneParser, MalformedTomlNamesTheLine) { expect_error("[film\nwidth = 3", {"bad.toml:1", "malformed TOML"}); }

TEST(SceneParser, UnknownKeyIsRejected) {
  expect_error(TestScene::minimal().table("film", {{"widht", 100}}).toml(), {"widht", "not a known key", "width"});
}

TEST(SceneParser, WrongTypeIsRejected) {
  expect_error(TestScene::minimal().table("film", {{"width", "big"}}).toml(), {"width", "\"big\"", "not an integer"});
}

TEST(SceneParser, OutOfRangeValueIsRejected) {
  expect_error(TestScene::minimal().film(0, 360).toml(), {"width", "out of range", "1 .. 16384"});
  expect_error(TestScene().material("m", {{"alpha", 1.5}}).sphere("m").point_light({0, 2, 3}).toml(), {"alpha", "1.5", "0 .. 1"});
}

TEST(SceneParser, AbsurdFilmSizeIsRejected) {
  expect_error(TestScene::minimal().film(16000, 16000).toml(), {"64 Mpixels"});
}

TEST(SceneParser, UnknownEnumValueListsTheAllowedOnes) {
  expect_error(TestScene().material("m", {{"ndf", "phong"}}).toml(), {"ndf", "phong", "ggx, beckmann"});
}

TEST(SceneParser, UnknownMaterialReferenceListsTheDefinedOnes) {
  expect_error(TestScene().material("m").sphere("x").point_light({0, 2, 3}).toml(), {"\"x\"", "defined: m"});
}

TEST(SceneParser, MissingRequiredKeyAndEmptySceneAreRejected) {
  expect_error(TestScene().light("point", {}).toml(), {"position", "required"});
  expect_error("", {"no [[shape]]"});
}

TEST(SceneParser, TooManyLightsAreRejected) {
  TestScene scene = TestScene::minimal();
  for (int i = 0; i < kMaxLights; ++i) scene.point_light({0, 1, 0});
  expect_error(scene.toml(), {std::to_string(kMaxLights + 1).c_str(), "at most 128"});
}

TEST(SceneParser, MissingAndBrokenFilesAreNamed) {
  const ScratchDirectory dir;
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
  std::ofstream(dir / "broken.png") << "not a png";
  try {
    static_cast<void>(
        TestScene().material("m").shape("mesh", "m", {{"file", "broken.obj"}}).point_light({0, 2, 3}).scene(dir.path()));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.obj"), std::string::npos) << e.what();
  }
  try {
    static_cast<void>(TestScene()
                          .material("m", {{"normal_map", TomlKeys{{"file", "broken.png"}}}})
                          .sphere("m")
                          .point_light({0, 2, 3})
                          .scene(dir.path()));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scene((dir / "missing.toml").string()), InputError);
}

TEST(SceneParser, ObjMeshLoadsWithTangents) {
  const ScratchDirectory dir;
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                     "f 1/1 2/2 3/3 4/4\n";
  const Scene s = TestScene().material("m").shape("mesh", "m", {{"file", "quad.obj"}}).point_light({0, 2, 3}).scene(dir.path());
  ASSERT_EQ(s.shapes[0].mesh->triangle_count(), 2u);
  for (const auto& n : s.shapes[0].mesh->normals) EXPECT_NEAR(std::abs(n.y), 1.0f, 1e-5f);
  for (const auto& tg : s.shapes[0].mesh->tangents) EXPECT_NEAR(tg.x, 1.0f, 1e-5f);
}

TEST(SceneParser, APathFrameAtTheTargetIsRejectedLikeAStaticCameraThere) {
  // A static camera at its target is rejected; so is a path that reaches it (it rendered black).
  expect_error(TestScene::minimal().camera({0, 1, 4}, {0, 1, 4}, 40).toml(), {"target", "equals the position"});
  const std::string dolly = TestScene::minimal()
                                .camera({0, 0, 4}, {0, 0, 0}, 40)
                                .raw("[camera.path]\ntype = \"dolly\"\nto = [0, 0, 0]\nframes = 5\n")
                                .toml();
  expect_error(dolly, {"path", "frame 4", "at its target"});
  // Looking straight down the up axis at some frame is as degenerate.
  const std::string keys = TestScene::minimal()
                               .camera({0, 0, 4}, {0, 0, 0}, 40)
                               .raw("[camera.path]\ntype = \"keyframes\"\nframes = 3\n"
                                    "[[camera.path.keys]]\nposition = [0, 0, 4]\ntarget = [0, 0, 0]\n"
                                    "[[camera.path.keys]]\nposition = [0, 4, 0]\ntarget = [0, 0, 0]\n")
                               .toml();
  expect_error(keys, {"path", "frame 2", "up"});
}

TEST(SceneParser, BinomialGlintsMaterialKeysAreCheckedAndNamed) {
  auto binomial = [](TomlKeys keys) {
    keys.insert(keys.begin(), {"type", "binomial-glints"});
    return TestScene().material("g", std::move(keys)).sphere("g").point_light({0, 2, 3});
  };
  const Scene s = binomial({{"alpha", 0.3}, {"log_density", 12}, {"microfacet_roughness", 0.03},
                            {"density_randomization", 0.5}, {"slope_grid_scale", 8}})
                      .scene();
  ASSERT_TRUE(s.materials[0].is("binomial-glints"));
  EXPECT_EQ(s.materials[0].ndf, Ndf::GGX);
  EXPECT_FLOAT_EQ(s.materials[0].kind_param("log_density"), 12.0f);
  EXPECT_FLOAT_EQ(s.materials[0].kind_param("microfacet_roughness"), 0.03f);
  EXPECT_FLOAT_EQ(s.materials[0].kind_param("density_randomization"), 0.5f);
  EXPECT_FLOAT_EQ(s.materials[0].kind_param("slope_grid_scale"), 8.0f);
  expect_error(binomial({{"alpha", 0.0}}).toml(), {"alpha", "0.01 .. 1"});
  expect_error(binomial({{"log_density", 60}}).toml(), {"log_density", "60", "0 .. 50"});
  expect_error(binomial({{"microfacet_roughness", 2}}).toml(), {"microfacet_roughness", "2", "0.0001 .. 1"});
  expect_error(binomial({{"density_randomization", -1}}).toml(), {"density_randomization", "-1", "0 .. 10"});
  expect_error(binomial({{"slope_grid_scale", 0}}).toml(), {"slope_grid_scale", "0.1 .. 1000"});
  expect_error(binomial({{"ndf", "beckmann"}}).toml(), {"ndf", "GGX"});
  expect_error(binomial({{"sigma", 0.1}}).toml(), {"sigma", "not a known key"});
  expect_error(TestScene().material("g", {{"type", "sparkly"}}).toml(), {"type", "glinty, binomial-glints"});
}

TEST(SceneParser, NormalMapGlintsMaterialKeysAreCheckedAndNamed) {
  auto material = [](TomlKeys keys) {
    keys.insert(keys.begin(), {"type", "normal-map-glints"});
    return TestScene().material("brushed", std::move(keys)).sphere("brushed").point_light({0, 2, 3});
  };
  const TomlKeys bumps{{"generator", "bumps"}, {"resolution", 32}, {"alpha", 0.2}, {"max_frequency", 8}};
  const Scene s = material({{"intrinsic_roughness", 0.02}, {"normal_map", bumps}}).scene();
  const Material& m = s.materials[0];
  ASSERT_TRUE(m.is("normal-map-glints"));
  ASSERT_NE(m.normal_map, nullptr);
  EXPECT_EQ(m.ndf, Ndf::Beckmann);
  EXPECT_FLOAT_EQ(m.alpha.x, std::sqrt(2.0f) * 0.02f);
  EXPECT_FLOAT_EQ(m.alpha.y, m.alpha.x);
  EXPECT_FLOAT_EQ(m.kind_param("intrinsic_roughness"), 0.02f);
  // The masking alpha is the whole microsurface's: the bumps' slopes have variance alpha^2 over the
  // texels (distinct integer frequencies are orthogonal on the grid), plus 2 sigma_r^2.
  EXPECT_NEAR(m.kind_param("masking_alpha"), std::sqrt(0.2 * 0.2 + 2 * 0.02 * 0.02), 0.01);
  // A flat map leaves the intrinsic Gaussian alone: alpha = sqrt(2) sigma_r, the default 0.01.
  const Scene flat = material({{"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 4}, {"alpha", 0}}}}).scene();
  EXPECT_FLOAT_EQ(flat.materials[0].kind_param("intrinsic_roughness"), 0.01f);
  EXPECT_NEAR(flat.materials[0].kind_param("masking_alpha"), std::sqrt(2.0) * 0.01, 1e-6);

  expect_error(material({{"intrinsic_roughness", 0.02}}).toml(), {"normal_map", "'brushed'", "required"});
  expect_error(material({{"intrinsic_roughness", 0.5}, {"normal_map", bumps}}).toml(),
               {"intrinsic_roughness", "0.5", "0.001 .. 0.3"});
  expect_error(material({{"intrinsic_roughness", 0}, {"normal_map", bumps}}).toml(),
               {"intrinsic_roughness", "0", "0.001 .. 0.3"});
  expect_error(material({{"alpha", 0.1}, {"normal_map", bumps}}).toml(), {"alpha", "intrinsic_roughness"});
  expect_error(material({{"ndf", "ggx"}, {"normal_map", bumps}}).toml(), {"ndf", "Beckmann"});
  expect_error(material({{"log_density", 10}, {"normal_map", bumps}}).toml(), {"log_density", "not a known key"});
  expect_error(TestScene().material("g", {{"type", "sparkly"}}).toml(), {"type", "normal-map-glints"});

  // A map of Wang tiles: its surface, tiles and seed reach the material's parameters (the shaders'
  // lattice); the tile size must fit the input; only normal-map-glints materials take one.
  auto wang = [&](TomlKeys tiles) {
    TomlKeys map = bumps;
    map.emplace_back("wang_tiles", std::move(tiles));
    return map;
  };
  const Scene tiled = material({{"normal_map", wang({{"tile_size", 16}, {"tiles", 40}, {"seed", 77}})}}).scene();
  const Material& t = tiled.materials[0];
  ASSERT_TRUE(t.normal_map->wang.has_value());
  EXPECT_EQ(t.normal_map->width, 64);
  EXPECT_EQ(t.normal_map->surface_width(), 640);
  EXPECT_FLOAT_EQ(t.kind_param("wang_tiles"), 40.0f);
  EXPECT_FLOAT_EQ(t.kind_param("wang_seed"), 77.0f);
  EXPECT_NE(tiled.content_hash(),
            material({{"normal_map", wang({{"tile_size", 16}, {"tiles", 40}, {"seed", 78}})}}).scene().content_hash());
  expect_error(material({{"normal_map", wang({{"tile_size", 33}})}}).toml(), {"wang_tiles", "tile_size = 33", "2 .. 32"});
  expect_error(material({{"normal_map", wang({{"tiles", 0}})}}).toml(), {"tiles", "1 .. 4096"});
  expect_error(material({{"normal_map", wang({{"size", 3}})}}).toml(), {"size", "not a known key"});
  expect_error(TestScene().material("m", {{"normal_map", wang({{"tile_size", 8}})}}).sphere("m").toml(),
               {"normal_map", "wang_tiles", "normal-map-glints", "microfacet"});
}
