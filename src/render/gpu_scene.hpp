#pragma once
// The scene on the GPU: one vertex array per shape, material and light buffers, normal-map
// textures (mipmapped, unnormalised averages kept for methods that need the normals' spread),
// textured materials' parameter textures, the meshes of visible area lights, and the precomputed
// tables its materials and methods read.
#include <array>
#include <map>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/gpu_contract.hpp"
#include "gl/objects.hpp"
#include "render/prefiltered_ndfs.hpp"
#include "tables/gpu_tables.hpp"
#include "scene/scene.hpp"

namespace glintlab {

/// Index range [x, y) of each light kind (by code, src/scene/lights/light_kind.hpp) in the kind-sorted
/// light buffer.
using LightRanges = std::vector<glm::ivec2>;

/// Tables a material's program variant reads in every method and in the reference: its kind's
/// (MaterialKind::tables; a glinty material's BRDF reads the glint dictionary).
std::vector<std::string> material_tables(const Material& material);

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

class GpuScene {
 public:
  /// `tables`: where precomputed tables are cached (handed down from the top: Session, a test).
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
  /// Binds a material's textures to their units and sets `program`'s per-draw texture transforms
  /// (uTextureTransforms, shaders/core/material.glsl); uMaterial selects its uniform-block entry.
  void bind_material(GLuint program, int material) const;
  /// The precomputed tables on the GPU. Those the materials' program variants read whatever the
  /// method (material_tables) are made resident on construction; a method's own
  /// (MethodDescriptor::tables) are added by require_tables, which the renderer calls before
  /// drawing with it. Residency is a cache of the scene's data, hence const.
  [[nodiscard]] const GpuTables& tables() const { return tables_; }
  /// The ids of the tables the materials read (material_tables of each), sorted: what the
  /// reference reads, so its cache key includes these tables' keys.
  [[nodiscard]] const std::vector<std::string>& material_table_ids() const { return material_table_ids_; }
  void require_tables(std::span<const std::string> ids) const { tables_.require(ids); }
  /// The normal-map-glints materials' prefiltered NDF pyramids (deng2022), made on first use.
  /// Residency is a cache of the scene's data, hence const.
  [[nodiscard]] PrefilteredNdfs& prefiltered_ndfs() const { return prefiltered_ndfs_; }
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
  std::map<const MaterialTexture*, gl::Texture> texture_objects_;  // shared between materials
  gl::Texture white_;  // 1x1 white: the texel of an absent texture
  mutable GpuTables tables_;
  mutable PrefilteredNdfs prefiltered_ndfs_;
  std::vector<std::string> material_table_ids_;
  gl::Buffer materials_;
  gl::Buffer lights_;
  LightRanges light_ranges_;
};

}  // namespace glintlab
