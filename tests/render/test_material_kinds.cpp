// The material-kind extension point: a kind is its self-registering descriptor and its GLSL file
// behind the material interface. tests/scene/materials/test-glinty.cpp adds `test-glinty`, a copy
// of `glinty`, to this binary as a contributor adds a kind: it is registered after the built-in
// kinds, parsed, packed and rendered, and every image of it equals glinty's, while a method that
// knows glinty by its code shades the copy as its smooth limit.
#include <gtest/gtest.h>

#include "gl_fixture.hpp"
#include "render/shader_contract.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

/// The copy's GLSL: glinty's file with the kind's prefix renamed, as a contributor copies it.
void add_test_glinty_module() {
  if (shaders().exists("materials/test-glinty.glsl")) return;
  std::string text = shaders().source("materials/glinty.glsl");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"gGlintyMaterial", "gTestGlintyMaterial"},
                                 {"glintyMaterial", "testGlintyMaterial"}})
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  shaders().add_source("materials/test-glinty.glsl", text);
}

/// A glinty sphere under a point light, its material of kind `kind`.
Scene glinty_scene(const std::string& kind) {
  return TestScene()
      .film(40, 30)
      .camera({0, 0.4, 3}, {0, 0, 0}, 35)
      .material("sparkle", {{"type", kind}, {"sigma", 0.15}, {"log_density", 14}, {"f0", 0.9}, {"diffuse", 0.05}})
      .sphere("sparkle", {{"radius", 0.8}, {"segments", 48}})
      .point_light({1, 2, 3}, 6)
      .scene();
}

bool bitwise_equal(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin());
}

}  // namespace

TEST(MaterialKinds, ACopiedKindIsRegisteredLastWithItsOwnCodeAndAccessors) {
  const MaterialKind& copy = find_material_kind("test-glinty");
  EXPECT_EQ(&all_material_kinds().back(), &copy);
  EXPECT_NE(copy.code(), find_material_kind("glinty").code());
  EXPECT_EQ(copy.define(), "MATERIAL_KIND_TEST_GLINTY");
  EXPECT_EQ(copy.glsl_prefix(), "testGlinty");
  // Its parameters' accessors and its module behind the material interface are generated.
  bool accessor = false, module = false;
  for (const auto& [path, text] : generated_shader_sources()) {
    accessor |= path == "generated/material_params.glsl" &&
                text.find("float testGlintyLogDensity(MaterialData m)") != std::string::npos;
    module |= path == material_kind_module(copy) && text.find("testGlintyMaterialSpecularCos(s, wo, wi)") != std::string::npos;
  }
  EXPECT_TRUE(accessor);
  EXPECT_TRUE(module);
}

TEST(MaterialKinds, ACopiedKindParsesAndHashesAsItsOriginal) {
  const Scene original = glinty_scene("glinty"), copy = glinty_scene("test-glinty");
  EXPECT_EQ(copy.materials[0].kind->id, "test-glinty");
  EXPECT_EQ(copy.materials[0].kind_params, original.materials[0].kind_params);
  EXPECT_EQ(copy.materials[0].alpha, original.materials[0].alpha);
  EXPECT_NE(copy.content_hash(), original.content_hash());  // a kind is part of what an image depends on
}

TEST(MaterialKinds, ACopiedKindRendersAsItsOriginalInTheReferenceAndAsItsSmoothLimitElsewhere) {
  add_test_glinty_module();
  SceneFixture original(glinty_scene("glinty")), copy(glinty_scene("test-glinty"));
  // The reference shades every kind through the material interface: the copy's code is the original's.
  const Frame reference = original.reference(4), copied_reference = copy.reference(4);
  EXPECT_TRUE(bitwise_equal(copied_reference.total, reference.total));
  EXPECT_TRUE(bitwise_equal(copied_reference.specular, reference.specular));
  EXPECT_GT(reference.specular.mean().g, 0.0f);
  // chermain2021 knows glinty by its code (MATERIAL_KIND_GLINTY): the copy is shaded as its smooth
  // limit, exactly as the same material of the default kind.
  Scene smooth_scene = glinty_scene("test-glinty");
  smooth_scene.materials[0].set_kind(default_material_kind());
  SceneFixture smooth(smooth_scene);
  const Frame on_copy = copy.method("chermain2021");
  EXPECT_TRUE(bitwise_equal(on_copy.total, smooth.method("chermain2021").total));
  EXPECT_FALSE(bitwise_equal(on_copy.specular, original.method("chermain2021").specular));
}
