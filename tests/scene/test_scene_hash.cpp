// Scene::content_hash is the reference cache's key: every field that changes an image must change
// it, or a stale reference is served. Each field of each struct is listed below with a change to
// it; the fields that cannot change an image are listed too, and must not change the key. A field
// added to a struct later fails the field counts until it is hashed (or listed as not affecting
// images) and added here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "scene/lights/environment_map.hpp"
#include "scene/lights/light_kind.hpp"
#include "test_scenes.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

/// Converts to anything: T{AnyField{}, ...} compiles for up to as many initializers as the
/// aggregate T has fields.
struct AnyField {
  template <typename T>
  operator T() const;
};

template <typename T, typename... Fields>
consteval std::size_t field_count() {
  if constexpr (requires { T{Fields{}..., AnyField{}}; })
    return field_count<T, Fields..., AnyField>();
  else
    return sizeof...(Fields);
}

// The number of fields this test knows for each struct of the scene.
static_assert(field_count<Film>() == 4);
static_assert(field_count<Camera>() == 8);
static_assert(field_count<CameraKey>() == 2);
static_assert(field_count<CameraPath>() == 6);
static_assert(field_count<Material>() == 14);
static_assert(field_count<TexturedMetalRough>() == 8);
static_assert(field_count<TextureSlot>() == 2);
static_assert(field_count<MaterialTexture>() == 5);
static_assert(field_count<NormalMap>() == 5);
static_assert(field_count<WangTiling>() == 3);
static_assert(field_count<Mesh>() == 5);
static_assert(field_count<Shape>() == 4);
static_assert(field_count<Light>() == 13);
static_assert(field_count<Scene>() == 10);

struct FieldChange {
  std::string field;
  std::function<void(Scene&)> change;
};

/// A scene in which every field is in use: two materials (one glinty with a normal map), two shapes,
/// and lights of the kinds that read every Light field (a light is hashed by what it renders: its
/// packed record and its emitter).
Scene base_scene() {
  Scene s = TestScene()
                .film(32, 24)
                .camera({0, 1, 4}, {0, 0, 0}, 40)
                .material("plain", {{"alpha", {0.1, 0.2}}, {"f0", 0.5}, {"diffuse", 0.2}})
                .glinty_material("glinty", {{"sigma", 0.1},
                                            {"rho", 0.2},
                                            {"f0", 0.9},
                                            {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 8}}}})
                .material("binomial", {{"type", "binomial-glints"}, {"alpha", 0.3}})
                .sphere("plain", {{"segments", 8}})
                .plane("glinty")
                .light("quad", {{"position", {0, 2, 0}}, {"direction", {0, -1, 0}}, {"up", {1, 0, 0}}})
                .disk_light({1, 2, 0}, {0, -1, 0}, 0.5, 1)
                .light("sun", {{"direction", {0, -1, 0}}, {"irradiance", 1}, {"angular_radius", 1}})
                .light("spot", {{"position", {0, 2, 1}}, {"direction", {0, -1, 0}}, {"inner_angle", 10}})
                .light("environment", {{"radiance", 0.5}, {"rotation", 10}})
                .scene();
  EXPECT_TRUE(s.materials[1].is("glinty"));
  EXPECT_NE(s.materials[1].normal_map, nullptr);
  EXPECT_TRUE(s.materials[2].is("binomial-glints"));
  // A textured material (as glTF import makes them), every slot with a texture.
  Material textured = s.materials[0];
  textured.name = "textured";
  auto texture = std::make_shared<MaterialTexture>(MaterialTexture{2, 2, std::vector<std::uint8_t>(16, 128), true, "test"});
  textured.textures = TexturedMetalRough{};
  textured.textures->base_color_texture.texture = texture;
  textured.textures->metallic_roughness_texture.texture = texture;
  textured.textures->emissive_texture.texture = texture;
  s.materials.push_back(textured);
  // A material of every other kind (the parser's fields, set by hand: the hash reads the struct).
  for (const MaterialKind& kind : all_material_kinds()) {
    if (std::any_of(s.materials.begin(), s.materials.end(), [&](const Material& m) { return m.kind == &kind; })) continue;
    Material other = s.materials[1];
    other.name = kind.id;
    other.set_kind(kind);
    s.materials.push_back(other);
  }
  return s;
}

TexturedMetalRough& textured_of(Scene& s) { return *s.materials[3].textures; }

std::shared_ptr<MaterialTexture> texture_of(Scene& s) {
  auto t = std::make_shared<MaterialTexture>(*textured_of(s).base_color_texture.texture);
  textured_of(s).base_color_texture.texture = t;
  return t;
}

std::shared_ptr<Mesh> mesh_of(Shape& shape) {
  auto mesh = std::make_shared<Mesh>(*shape.mesh);
  shape.mesh = mesh;
  return mesh;
}

std::shared_ptr<NormalMap> normal_map_of(Material& m) {
  auto map = std::make_shared<NormalMap>(*m.normal_map);
  m.normal_map = map;
  return map;
}

// Fields that change an image: each must change the key.
const std::vector<FieldChange> kHashed = {
    {"film.width", [](Scene& s) { s.film.width += 1; }},
    {"film.height", [](Scene& s) { s.film.height += 1; }},
    {"camera.projection", [](Scene& s) { s.camera.projection = Projection::Orthographic; }},
    {"camera.position", [](Scene& s) { s.camera.position.x += 0.1f; }},
    {"camera.target", [](Scene& s) { s.camera.target.y += 0.1f; }},
    {"camera.up", [](Scene& s) { s.camera.up.x += 0.1f; }},
    {"camera.fov_y_degrees", [](Scene& s) { s.camera.fov_y_degrees += 1; }},
    {"camera.view_height", [](Scene& s) { s.camera.view_height += 1; }},
    {"camera.near_plane", [](Scene& s) { s.camera.near_plane *= 2; }},
    {"camera.far_plane", [](Scene& s) { s.camera.far_plane *= 2; }},
    {"material.ndf", [](Scene& s) { s.materials[0].ndf = Ndf::Beckmann; }},
    {"material.alpha", [](Scene& s) { s.materials[0].alpha.y += 0.01f; }},
    {"material.rho", [](Scene& s) { s.materials[1].rho += 0.1f; }},
    {"material.f0", [](Scene& s) { s.materials[0].f0.g += 0.01f; }},
    {"material.diffuse", [](Scene& s) { s.materials[0].diffuse.b += 0.01f; }},
    {"material.normal_map (none -> one)", [](Scene& s) { s.materials[0].normal_map = s.materials[1].normal_map; }},
    {"material.normal_map_tiling", [](Scene& s) { s.materials[1].normal_map_tiling *= 2; }},
    {"material.normal_map_transform", [](Scene& s) { s.materials[1].normal_map_transform[2][0] += 0.5f; }},
    {"material.anisotropy_rotation", [](Scene& s) { s.materials[0].anisotropy_rotation += 0.1f; }},
    {"material.emission", [](Scene& s) { s.materials[0].emission.r += 0.1f; }},
    {"material.textures (one -> none)", [](Scene& s) { s.materials[3].textures.reset(); }},
    {"textured.base_color", [](Scene& s) { textured_of(s).base_color.a *= 0.5f; }},
    {"textured.metallic", [](Scene& s) { textured_of(s).metallic *= 0.5f; }},
    {"textured.roughness", [](Scene& s) { textured_of(s).roughness *= 0.5f; }},
    {"textured.anisotropy", [](Scene& s) { textured_of(s).anisotropy += 0.5f; }},
    {"textured.dielectric_f0", [](Scene& s) { textured_of(s).dielectric_f0.g += 0.01f; }},
    {"textured.base_color_texture", [](Scene& s) { textured_of(s).base_color_texture.texture.reset(); }},
    {"textured.metallic_roughness_texture",
     [](Scene& s) { textured_of(s).metallic_roughness_texture.transform[0][0] = 2.0f; }},
    {"textured.emissive_texture", [](Scene& s) { textured_of(s).emissive_texture.texture.reset(); }},
    {"slot.texture (one -> none)", [](Scene& s) { textured_of(s).emissive_texture.texture.reset(); }},
    {"slot.transform", [](Scene& s) { textured_of(s).base_color_texture.transform[2][1] = 0.25f; }},
    {"texture.width", [](Scene& s) { texture_of(s)->width = 1; }},
    {"texture.height", [](Scene& s) { texture_of(s)->height = 1; }},
    {"texture.rgba", [](Scene& s) { texture_of(s)->rgba[3] = 7; }},
    {"texture.srgb", [](Scene& s) { texture_of(s)->srgb = false; }},
    {"material.kind (binomial-glints -> microfacet)",
     [](Scene& s) { s.materials[2].set_kind(default_material_kind()); }},
    // Each parameter of each kind: SceneHash.EveryMaterialKindParameterChangesTheKey.
    {"material.kind_params", [](Scene& s) { s.materials[1].kind_params[0] += 1; }},
    {"normal_map.width", [](Scene& s) { normal_map_of(s.materials[1])->width += 1; }},
    {"normal_map.height", [](Scene& s) { normal_map_of(s.materials[1])->height += 1; }},
    {"normal_map.normals", [](Scene& s) { normal_map_of(s.materials[1])->normals[5].x += 0.01f; }},
    {"normal_map.wang (none -> tiles)",
     [](Scene& s) { normal_map_of(s.materials[1])->wang = WangTiling{.tile_size = 2, .tiles = 4, .seed = 1}; }},
    {"shape.transform", [](Scene& s) { s.shapes[0].transform[3][0] += 0.1f; }},
    {"shape.material", [](Scene& s) { s.shapes[0].material = 1; }},
    {"mesh.positions", [](Scene& s) { mesh_of(s.shapes[1])->positions[2].y += 0.01f; }},
    {"mesh.normals", [](Scene& s) { mesh_of(s.shapes[1])->normals[1].z += 0.01f; }},
    {"mesh.tangents", [](Scene& s) { mesh_of(s.shapes[1])->tangents[0].w *= -1; }},
    {"mesh.uvs", [](Scene& s) { mesh_of(s.shapes[1])->uvs[3].x += 0.01f; }},
    {"mesh.indices",
     [](Scene& s) {
       const auto mesh = mesh_of(s.shapes[1]);
       std::swap(mesh->indices[0], mesh->indices[1]);
     }},
    {"light.kind", [](Scene& s) { s.lights[0].kind = &find_light_kind("disk"); }},
    {"light.colour", [](Scene& s) { s.lights[0].colour.r += 0.1f; }},
    {"light.position", [](Scene& s) { s.lights[0].position.z += 0.1f; }},
    {"light.direction", [](Scene& s) { s.lights[0].direction.x += 0.1f; }},
    {"light.up", [](Scene& s) { s.lights[0].up.z += 0.1f; }},
    {"light.radius", [](Scene& s) { s.lights[1].radius += 0.1f; }},
    {"light.size", [](Scene& s) { s.lights[0].size.x += 0.1f; }},
    {"light.angular_radius_degrees", [](Scene& s) { s.lights[2].angular_radius_degrees += 1; }},
    {"light.visible", [](Scene& s) { s.lights[0].visible = !s.lights[0].visible; }},
    // A disk's up is in no record: it turns only its emitter's mesh about the normal.
    {"light.up (a disk's)", [](Scene& s) { s.lights[1].up = {1, 0, 0}; }},
    {"light.inner_angle_degrees", [](Scene& s) { s.lights[3].inner_angle_degrees += 1; }},
    {"light.outer_angle_degrees", [](Scene& s) { s.lights[3].outer_angle_degrees += 1; }},
    {"light.rotation_degrees", [](Scene& s) { s.lights[4].rotation_degrees += 5; }},
    {"light.environment",
     [](Scene& s) { s.lights[4].environment = std::make_shared<EnvironmentMap>(uniform_environment_map(glm::vec3(0.7f))); }},
    {"a material more", [](Scene& s) { s.materials.push_back(s.materials[0]); }},
    {"a shape more", [](Scene& s) { s.shapes.push_back(s.shapes[0]); }},
    {"a light more", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
};

// Fields that never change an image: names and provenance, the PNG-only film settings, and the
// camera path (the reference cache keys each frame by the camera the path gives it).
const std::vector<FieldChange> kNotHashed = {
    {"scene.name", [](Scene& s) { s.name = "other"; }},
    {"scene.source", [](Scene& s) { s.source = "other.toml"; }},
    {"scene.description", [](Scene& s) { s.description = "other"; }},
    {"film.exposure", [](Scene& s) { s.film.exposure += 1; }},
    {"film.bloom", [](Scene& s) { s.film.bloom += 1; }},
    {"path.type", [](Scene& s) { s.path.type = CameraPathType::Orbit; }},
    {"path.frames", [](Scene& s) { s.path.frames += 1; }},
    {"path.orbit_degrees", [](Scene& s) { s.path.orbit_degrees += 1; }},
    {"path.orbit_axis", [](Scene& s) { s.path.orbit_axis.x += 1; }},
    {"path.dolly_to", [](Scene& s) { s.path.dolly_to.x += 1; }},
    {"path.keys", [](Scene& s) { s.path.keys.push_back({}); }},
    {"material.name", [](Scene& s) { s.materials[0].name = "other"; }},
    {"scene.warnings", [](Scene& s) { s.warnings.push_back("other"); }},
    {"texture.description", [](Scene& s) { texture_of(s)->description = "other"; }},
    {"normal_map.description", [](Scene& s) { normal_map_of(s.materials[1])->description = "other"; }},
    {"shape.type", [](Scene& s) { s.shapes[0].type = "mesh"; }},
};

}  // namespace

TEST(SceneHash, EveryFieldThatChangesAnImageChangesTheKey) {
  const Scene base = base_scene();
  const auto key = base.content_hash();
  EXPECT_EQ(base_scene().content_hash(), key) << "the same scene, the same key";
  for (const auto& f : kHashed) {
    Scene s = base;
    f.change(s);
    EXPECT_NE(s.content_hash(), key) << f.field << " is not part of Scene::content_hash";
  }
}

TEST(SceneHash, NamesPathsAndDisplaySettingsDoNotChangeTheKey) {
  const Scene base = base_scene();
  for (const auto& f : kNotHashed) {
    Scene s = base;
    f.change(s);
    EXPECT_EQ(s.content_hash(), base.content_hash()) << f.field << " changes the key but not an image";
  }
}

TEST(SceneHash, EveryFieldIsListedOnce) {
  // The counts of the static_asserts above, as fields listed here: a struct's field is either
  // hashed or not, never both, never neither.
  auto count = [](const std::vector<FieldChange>& list, const std::string& prefix) {
    int n = 0;
    for (const auto& f : list)
      if (f.field.rfind(prefix, 0) == 0 && f.field.find(' ') == std::string::npos) ++n;
    return n;
  };
  auto fields = [&](const std::string& prefix) { return count(kHashed, prefix) + count(kNotHashed, prefix); };
  EXPECT_EQ(fields("film."), static_cast<int>(field_count<Film>()));
  EXPECT_EQ(fields("camera."), static_cast<int>(field_count<Camera>()));
  EXPECT_EQ(fields("path."), static_cast<int>(field_count<CameraPath>()));
  // material.kind, .normal_map and .textures are listed by what changes ("none -> one").
  EXPECT_EQ(fields("material.") + 3, static_cast<int>(field_count<Material>()));
  EXPECT_EQ(fields("textured."), static_cast<int>(field_count<TexturedMetalRough>()));
  EXPECT_EQ(fields("slot.") + 1, static_cast<int>(field_count<TextureSlot>()));
  EXPECT_EQ(fields("texture."), static_cast<int>(field_count<MaterialTexture>()));
  // normal_map.wang is listed by what changes ("none -> tiles"); its fields by the test below.
  EXPECT_EQ(fields("normal_map.") + 1, static_cast<int>(field_count<NormalMap>()));
  EXPECT_EQ(fields("mesh."), static_cast<int>(field_count<Mesh>()));
  // shape.mesh: its contents are the mesh.* fields.
  EXPECT_EQ(fields("shape.") + 1, static_cast<int>(field_count<Shape>()));
  EXPECT_EQ(fields("light."), static_cast<int>(field_count<Light>()));
  // Scene: name, source, description, and film, camera, path, materials, shapes, lights above.
  EXPECT_EQ(fields("scene.") + 6, static_cast<int>(field_count<Scene>()));
}

TEST(SceneHash, EveryWangTilingFieldChangesTheKey) {
  const WangTiling tiling{.tile_size = 2, .tiles = 4, .seed = 1};
  auto key_with = [](const WangTiling& w) {
    Scene s = base_scene();
    normal_map_of(s.materials[1])->wang = w;
    return s.content_hash();
  };
  const std::uint64_t key = key_with(tiling);
  EXPECT_NE(key_with({.tile_size = 4, .tiles = 4, .seed = 1}), key) << "tile_size";
  EXPECT_NE(key_with({.tile_size = 2, .tiles = 5, .seed = 1}), key) << "tiles";
  EXPECT_NE(key_with({.tile_size = 2, .tiles = 4, .seed = 2}), key) << "seed";
  EXPECT_EQ(key_with(tiling), key);
}

TEST(SceneHash, EveryMaterialKindParameterChangesTheKey) {
  // Each declared parameter of every registered kind is hashed; the record's unused slots are not.
  const Scene base = base_scene();
  const std::uint64_t key = base.content_hash();
  for (std::size_t m = 0; m < base.materials.size(); ++m) {
    const MaterialKind& kind = *base.materials[m].kind;
    for (std::size_t i = 0; i < static_cast<std::size_t>(kMaxMaterialKindParams); ++i) {
      Scene s = base;
      s.materials[m].kind_params[i] += 0.5f;
      if (i < kind.params.size())
        EXPECT_NE(s.content_hash(), key) << kind.id << "." << kind.params[i].key;
      else
        EXPECT_EQ(s.content_hash(), key) << kind.id << ": unused slot " << i;
    }
  }
}

namespace {

/// What images see of a light: its record, its emitter (none when not drawn) and, for a light
/// that is not compact, its map.
struct Rendered {
  LightGpu record;
  std::optional<LightEmitter> emitter;
  std::vector<glm::vec3> map;
};

Rendered rendered(const Light& l) {
  return {l.kind->pack(l), l.kind->emitter ? l.kind->emitter(l) : std::optional<LightEmitter>{},
          !l.kind->compact && l.environment ? l.environment->radiance.pixels() : std::vector<glm::vec3>{}};
}

bool same_bytes(const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same(const Rendered& a, const Rendered& b) {
  if (!same_bytes(a.record, b.record) || a.emitter.has_value() != b.emitter.has_value() || a.map != b.map) return false;
  if (!a.emitter) return true;
  const LightEmitter &x = *a.emitter, &y = *b.emitter;
  return same_bytes(x.transform, y.transform) && same_bytes(x.radiance, y.radiance) && x.two_sided == y.two_sided &&
         x.mesh.positions == y.mesh.positions && x.mesh.normals == y.mesh.normals && x.mesh.indices == y.mesh.indices;
}

}  // namespace

TEST(SceneHash, ALightChangesTheKeyExactlyWhenWhatItRendersChanges) {
  // Every kind, every Light field: the key follows the record the kind packs and the emitter it
  // draws, so a kind never lists its fields a third time (after parse and pack) for the hash.
  const std::vector<std::pair<std::string, std::function<void(Light&)>>> changes = {
      {"colour", [](Light& l) { l.colour.g += 0.25f; }},
      {"position", [](Light& l) { l.position.x += 0.25f; }},
      {"direction", [](Light& l) { l.direction = glm::normalize(glm::vec3(0.2f, -1, 0.1f)); }},
      {"up", [](Light& l) { l.up = {1, 0, 0}; }},
      {"radius", [](Light& l) { l.radius += 0.25f; }},
      {"size", [](Light& l) { l.size.y += 0.25f; }},
      {"angular_radius_degrees", [](Light& l) { l.angular_radius_degrees += 0.5f; }},
      {"inner_angle_degrees", [](Light& l) { l.inner_angle_degrees += 5; }},
      {"outer_angle_degrees", [](Light& l) { l.outer_angle_degrees += 5; }},
      {"visible", [](Light& l) { l.visible = !l.visible; }},
      {"rotation_degrees", [](Light& l) { l.rotation_degrees += 10; }},
      {"environment",
       [](Light& l) { l.environment = std::make_shared<EnvironmentMap>(uniform_environment_map(glm::vec3(0.3f))); }},
  };
  static_assert(field_count<Light>() == 13, "kind + the fields above");
  int changed = 0, kept = 0;
  for (const LightKind& kind : all_light_kinds()) {
    Scene base = base_scene();
    Light light;
    light.kind = &kind;
    light.radius = 0.5f;
    light.angular_radius_degrees = 1.0f;
    light.inner_angle_degrees = 10.0f;
    light.environment = std::make_shared<EnvironmentMap>(uniform_environment_map(glm::vec3(1.0f)));
    base.lights = {light};
    const std::uint64_t key = base.content_hash();
    for (const auto& [field, change] : changes) {
      Scene s = base;
      change(s.lights[0]);
      const bool renders_otherwise = !same(rendered(s.lights[0]), rendered(base.lights[0]));
      EXPECT_EQ(s.content_hash() != key, renders_otherwise)
          << kind.id << "." << field
          << (renders_otherwise ? " changes the image but not the key" : " changes the key only");
      ++(renders_otherwise ? changed : kept);
    }
  }
  EXPECT_GT(changed, 20);
  EXPECT_GT(kept, 20) << "e.g. a point light's radius, a spot's visible";
}
