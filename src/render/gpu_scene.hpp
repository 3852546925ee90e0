#pragma once
// The scene on the GPU: one vertex array per shape, material and light buffers, normal-map
// textures (mipmapped, unnormalised averages kept for methods that need the normals' spread),
// and the meshes of visible area lights.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "gl/objects.hpp"
#include "render/glint_dictionary_texture.hpp"
#include "scene/scene.hpp"

namespace glintlab {

/// Index range [x, y) of each light kind (by code, src/scene/light_kind.hpp) in the kind-sorted
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

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);

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
  [[nodiscard]] bool glinty(int material) const { return glinty_[index(material)]; }
  /// The glint dictionary (shaders/common/glint_dictionary.glsl), uploaded when a material is
  /// glinty; texture 0 otherwise.
  [[nodiscard]] const GlintDictionaryTexture& glint_dictionary() const { return glint_dictionary_; }
  /// The light buffer is sorted by kind; [x, y) is the index range of each kind.
  [[nodiscard]] const LightRanges& light_ranges() const { return light_ranges_; }
  /// Binds the material and light uniform buffers (kMaterialBlockBinding, kLightBlockBinding).
  void bind_buffers() const;

 private:
  struct NormalMapTextures {
    gl::Texture normals, slope_moments, slope_cross_moment;
  };
  static std::size_t index(int material) { return static_cast<std::size_t>(material); }
  static NormalMapTextures upload_normal_map(const NormalMap& map);

  std::vector<GpuMesh> meshes_;
  std::vector<GpuEmitter> emitters_;
  std::vector<NormalMapTextures> normal_maps_;
  std::vector<bool> glinty_;
  GlintDictionaryTexture glint_dictionary_;
  gl::Buffer materials_;
  gl::Buffer lights_;
  LightRanges light_ranges_;
};

}  // namespace glintlab
