#pragma once
// The scene on the GPU: one vertex array per shape, material and light buffers, normal-map
// textures (mipmapped, unnormalised averages kept for methods that need the normals' spread),
// textured materials' parameter textures, the meshes of visible area lights, and the resources
// (render/resources/) its material and light kinds and its methods read.
#include <array>
#include <map>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/gpu_contract.hpp"
#include "gl/objects.hpp"
#include "render/resources/resource_set.hpp"
#include "scene/scene.hpp"

namespace glintlab {

/// Index range [x, y) of each light kind (by code, src/scene/lights/light_kind.hpp) in the kind-sorted
/// light buffer.
using LightRanges = std::vector<glm::ivec2>;

struct GpuMesh {
  gl::VertexArray vao;
  gl::Buffer vertices;
  gl::Buffer indices;
  GLsizei index_count = 0;
  glm::mat4 transform{1.0f};
  int material = 0;
};

struct GpuEmitter {
  GpuMesh mesh;
  glm::vec3 radiance{0.0f};
  bool two_sided = false;
};

/// A light's record in the light block (shaders/lights/light_data.glsl): its kind's packing, tagged
/// with the kind's code. What an engine that binds an exported shader packs too (docs/export.md).
LightGpu pack_light(const Light& light);
/// A material's record in the material block (shaders/core/material.glsl).
MaterialGpu pack_material(const Material& material);

class GpuScene {
 public:
  /// `tables`: where precomputed tables (and other resources with a disk cache) are cached
  /// (handed down from the top: Session, a test). The scene must outlive this.
  GpuScene(const Scene& scene, TableCache tables);

  [[nodiscard]] const std::vector<GpuMesh>& meshes() const { return meshes_; }
  [[nodiscard]] const std::vector<GpuEmitter>& emitters() const { return emitters_; }
  /// Textures of a material's normal map (0 if it has none), all with full mip chains made by
  /// plain averaging: the normals (not renormalised, so their length measures their spread), the
  /// slope moments (Bx, By, Bx^2, By^2) with B = n.xy / n.z, and the cross moment Bx By.
  [[nodiscard]] GLuint normal_map(int material) const { return normal_maps_[index(material)].normals.id(); }
  [[nodiscard]] GLuint slope_moments(int material) const { return normal_maps_[index(material)].slope_moments.id(); }
  [[nodiscard]] GLuint slope_cross_moment(int material) const {
    return normal_maps_[index(material)].slope_cross_moment.id();
  }
  /// The material's kind (src/scene/materials/material_kind.hpp).
  [[nodiscard]] const MaterialKind& kind(int material) const { return *kinds_[index(material)]; }
  /// Whether the material's parameters vary per texel (Material::textures).
  [[nodiscard]] bool textured(int material) const { return textures_[index(material)].textured; }
  /// Whether the material's smooth lobe can be anisotropic (Material::anisotropic).
  [[nodiscard]] bool anisotropic(int material) const { return anisotropic_[index(material)]; }
  /// Whether the material's normal map is a surface of Wang tiles (NormalMap::wang).
  [[nodiscard]] bool wang_tiled(int material) const {
    const auto& map = scene_.materials[static_cast<std::size_t>(index(material))].normal_map;
    return map && map->wang;
  }
  /// Binds a material's textures to their units and sets `program`'s per-draw texture transforms
  /// (uTextureTransforms, shaders/core/material.glsl); uMaterial selects its uniform-block entry.
  void bind_material(GLuint program, int material) const;
  /// The resources the scene's material and light kinds read in every draw (scene_resources),
  /// made resident on construction: what the reference reads, so its cache key includes their keys.
  [[nodiscard]] const std::vector<std::string>& scene_resource_ids() const { return scene_resource_ids_; }
  /// Every resource resident for the scene, made on first request; what the scene's kinds read is
  /// resident from construction. Residency is a cache of the scene's data, hence const.
  [[nodiscard]] ResourceSet& resources() const { return resources_; }
  /// The context a resource of this scene is made in, with a method's parameters (none: a kind's).
  [[nodiscard]] ResourceContext resource_context(const ParamValues& params = no_params()) const {
    return {scene_, params, resources_.cache()};
  }
  static const ParamValues& no_params() {
    static const ParamValues none;
    return none;
  }
  /// The light-buffer index of the visible light that camera rays which miss the scene see (an
  /// environment: shaders/passes/background.frag), or -1.
  [[nodiscard]] int background_light() const { return background_light_; }
  /// The light buffer is sorted by kind; [x, y) is the index range of each kind.
  [[nodiscard]] const LightRanges& light_ranges() const { return light_ranges_; }
  /// Binds the material and light uniform buffers (kMaterialBlockBinding, kLightBlockBinding).
  void bind_buffers() const;

 private:
  struct NormalMapTextures {
    gl::Texture normals, slope_moments, slope_cross_moment;
  };
  /// A material's parameter textures (0: the factor alone, through a white texel) and the
  /// transforms of every slot (column-major 3x2, TEXTURE_SLOT_* order).
  struct MaterialTextures {
    bool textured = false;
    GLuint base_color = 0, metallic_roughness = 0, emissive = 0;
    std::array<float, 6 * kTextureSlots> transforms{};
  };
  static std::size_t index(int material) { return static_cast<std::size_t>(material); }
  static NormalMapTextures upload_normal_map(const NormalMap& map);
  GLuint upload_texture(const std::shared_ptr<const MaterialTexture>& texture);
  MaterialTextures material_textures(const Material& material);

  std::vector<GpuMesh> meshes_;
  std::vector<GpuEmitter> emitters_;
  std::vector<NormalMapTextures> normal_maps_;
  std::vector<const MaterialKind*> kinds_;
  std::vector<MaterialTextures> textures_;
  std::vector<bool> anisotropic_;
  std::map<const MaterialTexture*, gl::Texture> texture_objects_;  // shared between materials
  gl::Texture white_;  // 1x1 white: the texel of an absent texture
  const Scene& scene_;
  mutable ResourceSet resources_;
  std::vector<std::string> scene_resource_ids_;
  gl::Buffer materials_;
  gl::Buffer lights_;
  LightRanges light_ranges_;
  int background_light_ = -1;
};

}  // namespace glintlab
