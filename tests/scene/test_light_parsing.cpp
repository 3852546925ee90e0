// Light kinds in the scene format: each registered kind parses its own keys; `sun` is a kind, and
// a directional light with an angular radius is the same sun; an unknown type lists the kinds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/scene_loader.hpp"

using namespace glintlab;

namespace {

Scene with_light(const std::string& light) {
  return parse_scene("[[material]]\nname = \"m\"\n[[shape]]\ntype = \"sphere\"\nmaterial = \"m\"\n[[light]]\n" + light,
                     "lights.toml", ".");
}

std::string error_of(const std::string& light) {
  try {
    with_light(light);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LightKinds, RegistryHoldsEachKindOnceWithItsCode) {
  std::set<std::string> ids;
  for (const auto& k : all_light_kinds()) {
    EXPECT_TRUE(ids.insert(k.id).second) << k.id << " registered twice";
    EXPECT_EQ(&all_light_kinds()[static_cast<std::size_t>(k.code())], &k);
    // The id names the GLSL file and prefixes its functions: a GLSL identifier in lower case.
    for (char c : k.id) EXPECT_TRUE(c >= 'a' && c <= 'z') << k.id;
    EXPECT_TRUE(k.parse && k.pack) << k.id;
    EXPECT_EQ(k.has_extent && k.compact, k.form != LightForm::None)
        << k.id << ": delta lights and lights that are not compact have no form, the others one";
    EXPECT_TRUE(k.compact || (k.has_extent && k.distant)) << k.id << ": a light that is not compact surrounds the scene";
  }
  EXPECT_EQ(&find_light_kind("sun"), &all_light_kinds()[static_cast<std::size_t>(find_light_kind("sun").code())]);
}

TEST(SceneParser, SunIsALightKind) {
  const Scene s = with_light("type = \"sun\"\ndirection = [0, -2, 0]\nirradiance = 3\nangular_radius = 0.5\n");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].kind->id, "sun");
  EXPECT_FLOAT_EQ(s.lights[0].angular_radius_degrees, 0.5f);
  EXPECT_FLOAT_EQ(s.lights[0].direction.y, -1.0f) << "normalised";
  EXPECT_FLOAT_EQ(s.lights[0].colour.g, 3.0f);
  EXPECT_FLOAT_EQ(with_light("type = \"sun\"\ndirection = [0, -1, 0]\n").lights[0].angular_radius_degrees, 0.27f)
      << "the documented default";
  EXPECT_NE(error_of("type = \"sun\"\ndirection = [0, -1, 0]\nangular_radius = 0\n").find("angular_radius"),
            std::string::npos)
      << "a sun of no extent is a directional light";
}

TEST(SceneParser, DirectionalLightWithAnAngularRadiusIsTheSun) {
  // Scenes written before the sun kind: the same light, the same cache key.
  const Scene legacy = with_light("type = \"directional\"\ndirection = [0.2, -0.3, 1.0]\nirradiance = 0.5\nangular_radius = 0.5\n");
  const Scene sun = with_light("type = \"sun\"\ndirection = [0.2, -0.3, 1.0]\nirradiance = 0.5\nangular_radius = 0.5\n");
  EXPECT_EQ(legacy.lights[0].kind, &find_light_kind("sun"));
  EXPECT_EQ(legacy.content_hash(), sun.content_hash());
  const Scene delta = with_light("type = \"directional\"\ndirection = [0.2, -0.3, 1.0]\nirradiance = 0.5\n");
  EXPECT_EQ(delta.lights[0].kind, &find_light_kind("directional"));
  EXPECT_NE(delta.content_hash(), sun.content_hash());
}

TEST(SceneParser, UnknownLightTypeListsTheRegisteredKinds) {
  const std::string msg = error_of("type = \"lamp\"\nposition = [0, 1, 0]\n");
  ASSERT_FALSE(msg.empty());
  EXPECT_NE(msg.find("lights.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lamp"), std::string::npos) << msg;
  for (const auto& id : light_kind_ids()) EXPECT_NE(msg.find(id), std::string::npos) << id << " not in: " << msg;
  EXPECT_THROW(find_light_kind("lamp"), InputError);
}

TEST(SceneParser, SpotLightReadsItsConeInDegrees) {
  const Scene s = with_light("type = \"spot\"\nposition = [0, 2, 0]\ndirection = [0, -3, 0]\nintensity = [1, 2, 3]\n"
                             "inner_angle = 10\nouter_angle = 20\n");
  ASSERT_EQ(s.lights[0].kind, &find_light_kind("spot"));
  EXPECT_FLOAT_EQ(s.lights[0].direction.y, -1.0f) << "normalised";
  EXPECT_FLOAT_EQ(s.lights[0].colour.b, 3.0f);
  EXPECT_FLOAT_EQ(s.lights[0].inner_angle_degrees, 10.0f);
  EXPECT_FLOAT_EQ(s.lights[0].outer_angle_degrees, 20.0f);
  const Scene defaults = with_light("type = \"spot\"\nposition = [0, 2, 0]\ndirection = [0, -1, 0]\n");
  EXPECT_FLOAT_EQ(defaults.lights[0].inner_angle_degrees, 0.0f) << "KHR_lights_punctual's default";
  EXPECT_FLOAT_EQ(defaults.lights[0].outer_angle_degrees, 45.0f) << "KHR_lights_punctual's default";
  EXPECT_NO_THROW(with_light("type = \"spot\"\nposition = [0, 2, 0]\ndirection = [0, -1, 0]\nouter_angle = 90\n"));
}

TEST(SceneParser, SpotLightAnglesAndDirectionAreChecked) {
  // Each error names the key, the value and what is allowed.
  const std::string spot = "type = \"spot\"\nposition = [0, 2, 0]\n";
  auto expect_error = [&](const std::string& keys, std::initializer_list<const char*> parts) {
    const std::string msg = error_of(spot + keys);
    ASSERT_FALSE(msg.empty()) << keys;
    for (const char* part : parts) EXPECT_NE(msg.find(part), std::string::npos) << part << " not in: " << msg;
  };
  const std::string down = "direction = [0, -1, 0]\n";
  expect_error(down + "inner_angle = 30\nouter_angle = 30\n", {"inner_angle", "30", "inner_angle < outer_angle"});
  expect_error(down + "inner_angle = 50\n", {"inner_angle", "50", "45", "inner_angle < outer_angle"});
  expect_error(down + "inner_angle = -1\n", {"inner_angle", "-1", "0 .. 90"});
  expect_error(down + "outer_angle = 90.5\n", {"outer_angle", "90.5", "0 .. 90"});
  expect_error(down + "outer_angle = 0\n", {"inner_angle", "inner_angle < outer_angle"});
  expect_error("direction = [0, 0, 0]\n", {"direction", "zero vector"});
  expect_error("", {"direction", "required"});
  expect_error(down + "range = 10\n", {"range"});
  EXPECT_NE(error_of("type = \"spot\"\n" + down).find("position"), std::string::npos);
}

TEST(SceneParser, LightHashSeesTheParametersItsKindReads) {
  const std::string quad = "type = \"quad\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\n";
  const auto base = with_light(quad).content_hash();
  EXPECT_NE(with_light(quad + "up = [1, 0, 0]\n").content_hash(), base);
  EXPECT_NE(with_light(quad + "size = [1, 2]\n").content_hash(), base);
  EXPECT_NE(with_light(quad + "visible = false\n").content_hash(), base);
  const std::string sun = "type = \"sun\"\ndirection = [0, -1, 0]\n";
  EXPECT_NE(with_light(sun + "angular_radius = 1\n").content_hash(), with_light(sun).content_hash());
  const std::string spot = "type = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\n";
  const auto spot_base = with_light(spot).content_hash();
  EXPECT_NE(with_light(spot + "inner_angle = 1\n").content_hash(), spot_base);
  EXPECT_NE(with_light(spot + "outer_angle = 40\n").content_hash(), spot_base);
  EXPECT_NE(with_light("type = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0.1]\n").content_hash(), spot_base);
}

TEST(LightKinds, SceneFormatDocumentsEveryKind) {
  // docs/scene-format.md has a row of keys for each registered kind.
  std::ifstream in(std::filesystem::path(GLINTLAB_TEST_DATA).parent_path().parent_path() / "docs" / "scene-format.md");
  ASSERT_TRUE(in) << "docs/scene-format.md";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const auto begin = doc.find("## `[[light]]`");
  ASSERT_NE(begin, std::string::npos);
  const std::string section = doc.substr(begin, doc.find("\n## ", begin + 1) - begin);
  for (const auto& id : light_kind_ids())
    EXPECT_NE(section.find("| `" + id + "` |"), std::string::npos) << "no row for the light kind " << id;
}
