#include "scene/gltf/gltf_shape.hpp"

#include <algorithm>
#include <optional>

#include "core/error.hpp"
#include "scene/gltf/gltf_showcase.hpp"
#include "scene/gltf/gltf_writer.hpp"
#include "scene/materials/material_parser.hpp"

namespace glintlab {

namespace {

/// A glTF file of the scene: a path relative to the scene file, or one of glintlab's own models
/// ("builtin:showcase.glb", made by the glTF writer in memory: no file, no download).
GltfAsset import_gltf_file(const std::string& file, const std::filesystem::path& base_dir) {
  if (file.rfind("builtin:", 0) != 0) return import_gltf(base_dir / file);
  if (file != "builtin:showcase.glb")
    throw InputError("value \"" + file + "\" names no built-in model; allowed: builtin:showcase.glb");
  return import_glb(gltf::encode_glb(gltf::make_showcase_document()), file);
}

}  // namespace

bool is_gltf(const std::string& file) {
  const auto ext = std::filesystem::path(file).extension().string();
  return ext == ".gltf" || ext == ".glb";
}

void add_gltf(TomlReader& r, const glm::mat4& transform, const std::map<std::string, int>& materials,
              const std::filesystem::path& base_dir, Scene& scene, std::vector<GltfCamera>& cameras) {
  const auto file = r.require_string("file");
  GltfAsset asset;
  try {
    asset = import_gltf_file(file, base_dir);
  } catch (const InputError& e) {
    r.fail("file", e.what());
  }
  std::optional<int> for_all;
  if (r.has("material")) for_all = material_named(r, "material", r.require_string("material"), materials);
  // Overrides by name: "mesh" (all its primitives) or "mesh#i" (one).
  std::map<std::string, int> overrides;
  if (const toml::table* t = r.get_table("materials")) {
    for (auto&& [key, value] : *t) {
      const auto name = value.value<std::string>();
      if (!name) r.fail("materials", "entry \"" + std::string(key.str()) + "\" is not a string naming a [[material]]");
      const std::string k(key.str());
      const bool known = std::any_of(asset.primitives.begin(), asset.primitives.end(), [&](const GltfPrimitive& p) {
        return p.mesh_name == k || p.mesh_name + "#" + std::to_string(p.primitive) == k;
      });
      if (!known) {
        std::string names;
        for (const auto& p : asset.primitives)
          if (names.find(p.mesh_name) == std::string::npos) names += (names.empty() ? "" : ", ") + p.mesh_name;
        r.fail("materials", "entry \"" + k + "\" names no mesh of " + file + "; its meshes: " + names +
                                " (or MESH#N for one primitive)");
      }
      overrides[k] = material_named(r, "materials", *name, materials);
    }
  }
  const bool with_lights = r.get_bool("lights", true);
  const bool with_cameras = r.get_bool("cameras", true);
  r.finish();

  std::map<int, int> file_material;  // the file's material -> the scene's, added when first used
  for (const GltfPrimitive& p : asset.primitives) {
    Shape shape;
    shape.type = "mesh";
    shape.mesh = p.mesh;
    shape.transform = transform * p.transform;
    if (auto it = overrides.find(p.mesh_name + "#" + std::to_string(p.primitive)); it != overrides.end())
      shape.material = it->second;
    else if (auto it2 = overrides.find(p.mesh_name); it2 != overrides.end())
      shape.material = it2->second;
    else if (for_all)
      shape.material = *for_all;
    else {
      auto [it3, added] = file_material.try_emplace(p.material, static_cast<int>(scene.materials.size()));
      if (added) scene.materials.push_back(asset.materials[static_cast<std::size_t>(p.material)]);
      shape.material = it3->second;
    }
    scene.shapes.push_back(std::move(shape));
  }
  const glm::mat3 linear(transform);
  if (with_lights)
    for (Light l : asset.lights) {
      l.position = glm::vec3(transform * glm::vec4(l.position, 1.0f));
      l.direction = glm::normalize(linear * l.direction);
      scene.lights.push_back(l);
    }
  if (with_cameras)
    for (GltfCamera c : asset.cameras) {
      c.camera.position = glm::vec3(transform * glm::vec4(c.camera.position, 1.0f));
      c.camera.target = glm::vec3(transform * glm::vec4(c.camera.target, 1.0f));
      c.camera.up = glm::normalize(linear * c.camera.up);
      cameras.push_back(c);
    }
  for (auto& w : asset.warnings) scene.warnings.push_back(std::move(w));
}

}  // namespace glintlab
