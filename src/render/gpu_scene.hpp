#pragma once
// The scene on the GPU: one vertex array per shape, material and light buffers, normal-map
// textures (mipmapped, unnormalised averages kept for methods that need the normals' spread),
// and the meshes of visible area lights.
#include <glm/mat4x4.hpp>
#include <vector>

#include "gl/objects.hpp"
#include "scene/scene.hpp"

namespace glintlab {

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
  /// Normal-map texture of a material, 0 if it has none.
  [[nodiscard]] GLuint normal_map(int material) const { return normal_maps_[static_cast<std::size_t>(material)].id(); }
  [[nodiscard]] int light_count() const { return light_count_; }
  /// Binds the material (binding 2) and light (binding 1) buffers.
  void bind_buffers() const;

 private:
  std::vector<GpuMesh> meshes_;
  std::vector<GpuEmitter> emitters_;
  std::vector<gl::Texture> normal_maps_;
  gl::Buffer materials_;
  gl::Buffer lights_;
  int light_count_ = 0;
};

}  // namespace glintlab
