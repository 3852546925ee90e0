#pragma once
// A [[shape]] of type "mesh" whose file is glTF (docs/scene-format.md, "glTF files"): the file's
// primitives, materials, lights and cameras added to the scene.
#include <filesystem>
#include <glm/mat4x4.hpp>
#include <map>
#include <string>
#include <vector>

#include "scene/gltf/gltf_import.hpp"
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

/// Whether a mesh file is glTF (.gltf, .glb).
bool is_gltf(const std::string& file);

/// A glTF file's place in the scene: its primitives as shapes with their own materials (or the
/// scene's, by `material` for all or `materials` by mesh name / "mesh#primitive"), its lights and
/// its cameras, all moved by the shape's `transform`.
void add_gltf(TomlReader& r, const glm::mat4& transform, const std::map<std::string, int>& materials,
              const std::filesystem::path& base_dir, Scene& scene, std::vector<GltfCamera>& cameras);

}  // namespace glintlab
