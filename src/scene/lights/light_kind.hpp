#pragma once
// A kind of light (Mitsuba 3's plugins, pbrt-v4's one concept per file): this descriptor, in
// src/scene/lights/<id>.cpp, plus the GLSL file shaders/lights/<id>.glsl with a fixed set of
// functions, and one entry in the registry (src/scene/lights/light_kinds.cpp). The registry's order is
// the kinds' codes on the GPU and the order in which the light loop shades them. The GLSL
// dispatch (lightHit, lightPdf, ...) and the light loop's call list are generated from the
// registry (src/render/shader_contract.cpp); docs/extending.md says how to add a kind.
#include <filesystem>
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/gpu_contract.hpp"
#include "scene/lights/light.hpp"
#include "scene/mesh.hpp"

namespace glintlab {

class TomlReader;

/// The shape a kind offers methods that integrate over a light (e.g. LTC, Podee's reflection
/// space): a disk (disks; spheres and suns as the disk facing the shading point that subtends their
/// cone), a polygon (quads), or none (delta lights). See shaders/lights/light_shapes.glsl.
enum class LightForm { None = 0, Disk = 1, Polygon = 2 };

/// The mesh that draws a visible light with extent, in world space.
struct LightEmitter {
  Mesh mesh;
  glm::mat4 transform{1.0f};
  glm::vec3 radiance{0.0f};
  bool two_sided = false;  ///< emits from both faces (a sphere's inside is never seen)
};

struct LightKind {
  std::string id;       ///< the scene file's `type`; GLSL: shaders/lights/<id>.glsl, functions <id>Light*
  bool has_extent = false;  ///< integrated over a solid angle; false: a delta light (incidence only)
  bool distant = false;     ///< at infinity: the same directions from every point
  LightForm form = LightForm::None;
  /// A compact emitter: one radiance over a bounded extent with a centre, an outline and a
  /// representative point (shaders/lights/lights.glsl). False for a light around the whole
  /// sphere whose radiance varies with direction (an environment): methods then shade it through
  /// lightRadianceFrom and their own resources, never through the compact interface.
  bool compact = true;
  /// Reads the kind's keys (after `type`) into a Light whose kind is set; validates them. Files a
  /// kind reads are relative to `base_dir` (the scene file's folder). May return another kind (a
  /// directional light with an angular radius is a sun).
  Light (*parse)(TomlReader& reader, const std::filesystem::path& base_dir) = nullptr;
  /// The GPU record; colour_type.w (the code) is set by the caller. It and the emitter are all
  /// that images see of a light, so they are what Scene::content_hash hashes (with the kind's id):
  /// a kind has no hash of its own to keep in step with its fields.
  LightGpu (*pack)(const Light& light) = nullptr;
  /// The emitter mesh of a visible light with extent; nullopt when it is not drawn.
  std::optional<LightEmitter> (*emitter)(const Light& light) = nullptr;
  /// The resources the kind's GLSL reads (src/render/resources/resource.hpp): its textures, CDFs,
  /// tables ("table:<id>"), made for the scene's lights of the kind.
  std::vector<std::string> resources = {};

  [[nodiscard]] std::string glsl_file() const { return "lights/" + id + ".glsl"; }
  /// Prefix of the kind's GLSL functions, e.g. "sunLight" for sunLightSample.
  [[nodiscard]] std::string glsl_prefix() const { return id + "Light"; }
  /// The kind's code on the GPU: LIGHT_<ID> in GLSL, its position in the registry.
  [[nodiscard]] int code() const;
};

/// Every kind, in the order of their codes.
const std::vector<LightKind>& all_light_kinds();
/// Throws InputError naming the registered kinds when there is none of that id.
const LightKind& find_light_kind(const std::string& id);
/// The registered ids in registry order.
std::vector<std::string> light_kind_ids();

}  // namespace glintlab
