#pragma once
// glintlab's own glTF 2.0 writer: tests and the `gltf-showcase` scene load glTF files that glintlab
// generates, because the repository ships no third-party assets. The Document holds everything in
// glTF's own conventions (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html):
//  - uv origin at the top-left of the image, v pointing down (row 0 of an Image8 is the top);
//  - tangent-space normal maps: +X along +u (right in the image), +Y up in the image, +Z out of the
//    surface; TANGENT.w is the handedness: bitangent = cross(normal, tangent.xyz) * w, and it points
//    up in the image (along -dP/dv);
//  - y up, metres, lights and cameras look along their node's -Z.
// The writer serialises with TinyGLTF; images are PNG (stb_image_write) in buffer views, so a .glb
// and a .gltf (one data-URI buffer) are self-contained.
#include <cstdint>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glintlab::gltf {

/// 8-bit RGBA, row-major, row 0 = top of the image.
struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

/// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv.
struct TextureTransform {
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;
};

/// An image index into Document::images (-1: no texture) and an optional transform.
struct TextureRef {
  int image = -1;
  std::optional<TextureTransform> transform;
};

struct MaterialDesc {
  std::string name;
  glm::vec4 base_color{1.0f};
  TextureRef base_color_texture;
  float metallic = 1.0f, roughness = 1.0f;
  TextureRef metallic_roughness_texture;  ///< G = roughness, B = metallic (linear)
  TextureRef normal_texture;
  float normal_scale = 1.0f;
  glm::vec3 emissive{0.0f};
  TextureRef emissive_texture;
  std::optional<float> emissive_strength;                ///< KHR_materials_emissive_strength
  std::optional<glm::vec2> anisotropy;                   ///< KHR_materials_anisotropy: (strength, rotation in radians)
  std::optional<float> ior;                              ///< KHR_materials_ior
  std::optional<std::pair<float, glm::vec3>> specular;   ///< KHR_materials_specular: factor, colour factor
  bool double_sided = false;
  /// Further extensions written as empty objects ({}: the extension's defaults) and listed in
  /// extensionsUsed, so an importer's "not implemented" warning can be tested.
  std::vector<std::string> extra_extensions;
};

/// One triangle list. normals, uvs and (if not empty) tangents have one entry per position.
struct PrimitiveDesc {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec4> tangents;  ///< optional: empty = no TANGENT attribute
  std::vector<glm::vec2> uvs;       ///< TEXCOORD_0, glTF convention (v down)
  std::vector<std::uint32_t> indices;
  int material = -1;
};

struct MeshDesc {
  std::string name;
  std::vector<PrimitiveDesc> primitives;
};

/// KHR_lights_punctual. Intensity in lux (directional) or candela (point, spot).
struct LightDesc {
  std::string name;
  std::string type = "point";  ///< directional | point | spot
  glm::vec3 colour{1.0f};
  float intensity = 1.0f;
  std::optional<float> range;
  float inner_cone = 0.0f, outer_cone = 0.785398f;  ///< spot only, radians
};

struct CameraDesc {
  std::string name;
  bool perspective = true;
  float yfov = 0.8f, aspect = 0.0f /*0: unset*/, znear = 0.05f, zfar = 100.0f;
  float xmag = 1.0f, ymag = 1.0f;  ///< orthographic only
};

struct NodeDesc {
  std::string name;
  int mesh = -1, light = -1, camera = -1;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  ///< glm order (w, x, y, z); written as glTF's [x, y, z, w]
  glm::vec3 scale{1.0f};
  std::optional<glm::mat4> matrix;  ///< replaces translation/rotation/scale when set
  std::vector<int> children;
};

struct Document {
  std::vector<Image8> images;
  std::vector<MaterialDesc> materials;
  std::vector<MeshDesc> meshes;
  std::vector<LightDesc> lights;
  std::vector<CameraDesc> cameras;
  std::vector<NodeDesc> nodes;
  std::vector<int> scene_nodes;  ///< roots of the one (default) scene; empty: no scene written
  /// Listed in extensionsUsed without being used anywhere (tests an importer's warnings).
  std::vector<std::string> extra_extensions_used;
};

/// Binary glTF (.glb) in memory. Throws InputError if the document is inconsistent (an index out
/// of range, attribute counts that differ, a non-triangle index count, an empty image...).
std::vector<std::uint8_t> encode_glb(const Document& doc);
/// The .gltf JSON text, every buffer embedded as a data URI.
std::string encode_gltf_json(const Document& doc);
/// Writes `.glb` (binary) or `.gltf` (JSON with data URIs) by the path's extension, atomically
/// (core/atomic_file.hpp). Throws InputError for another extension, RuntimeFailure on I/O failure.
void write_gltf(const std::filesystem::path& path, const Document& doc);

}  // namespace glintlab::gltf
