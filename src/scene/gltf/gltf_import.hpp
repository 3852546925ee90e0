#pragma once
// glTF 2.0 import (.gltf, .glb, or a .glb in memory): every primitive keeps its own material and
// its node's transform; KHR_lights_punctual lights and cameras come along. Everything is turned
// into glintlab's conventions on the way in (docs/scene-format.md, "glTF import"):
// - uv: glintlab's v points up, glTF's down, so v = 1 - v_glTF, and every texture's rows are
//   stored bottom first; KHR_texture_transform is conjugated by that flip.
// - tangent frames: the file's TANGENT (xyz along +u, w the handedness: bitangent =
//   w cross(normal, tangent), along +v, which is "up" in a glTF normal map), else one computed
//   from the uv gradients (compute_tangents).
// - units: point and spot intensities [cd] become intensities [W/sr] and directional illuminance
//   [lx] irradiance [W/m^2], one to one.
#include <cstdint>
#include <filesystem>
#include <glm/mat4x4.hpp>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "scene/lights/light.hpp"
#include "scene/materials/material.hpp"
#include "scene/mesh.hpp"

namespace glintlab {

struct GltfPrimitive {
  std::string mesh_name;             ///< the glTF mesh's name ("mesh<N>" when it has none)
  int primitive = 0;                 ///< index in the mesh's primitive list
  std::shared_ptr<const Mesh> mesh;  ///< the mesh's own space (shared by every node that uses it)
  glm::mat4 transform{1.0f};         ///< the node's transform in the file's world
  int material = 0;                  ///< index into GltfAsset::materials
};

struct GltfCamera {
  std::string name;
  Camera camera;
};

struct GltfAsset {
  std::vector<Material> materials;  ///< the file's materials, then glTF's default material if used
  std::vector<GltfPrimitive> primitives;
  std::vector<Light> lights;        ///< in the file's world
  std::vector<GltfCamera> cameras;  ///< one per node with a camera, in the file's world
  std::vector<std::string> warnings;  ///< what the file has that glintlab ignores, for the user
};

/// Throws InputError naming the file, and the element (mesh, accessor, material, image, node) and
/// the value, when the file is missing, malformed, needs an extension glintlab lacks or exceeds a
/// limit (docs/scene-format.md).
GltfAsset import_gltf(const std::filesystem::path& path);
/// The same for a binary glTF (.glb) in memory; `name` stands for the file in messages.
GltfAsset import_glb(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace glintlab
