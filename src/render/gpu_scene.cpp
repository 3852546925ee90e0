#include "render/gpu_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>

#include "gl/context.hpp"

namespace glintlab {

GpuLightKind gpu_light_kind(const Light& light) {
  switch (light.type) {
    case LightType::Point: return GpuLightKind::Point;
    case LightType::Directional:
      return light.angular_radius_degrees > 0.0f ? GpuLightKind::Sun : GpuLightKind::Directional;
    case LightType::Disk: return GpuLightKind::Disk;
    case LightType::Sphere: return GpuLightKind::Sphere;
    case LightType::Quad: return GpuLightKind::Quad;
  }
  return GpuLightKind::Point;
}

std::vector<std::string> material_tables(const Material& material) {
  if (material.glints) return {"glint-dictionary"};
  return {};
}

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 tangent;
  glm::vec2 uv;
};

// Mirrors MaterialData in shaders/common/material.glsl (std430).
struct MaterialGpu {
  glm::vec4 f0_ndf;
  glm::vec4 diffuse_tiling;
  glm::vec4 alpha_rho;
  glm::vec4 glints;
};

// Mirrors LightData in shaders/common/lights.glsl (std140).
struct LightGpu {
  glm::vec4 colour_type;
  glm::vec4 position_radius;
  glm::vec4 direction_cos;
  glm::vec4 axis_u;
  glm::vec4 axis_v;
};

GpuMesh upload(const Mesh& mesh, const glm::mat4& transform, int material) {
  std::vector<Vertex> vertices(mesh.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = {mesh.positions[i], mesh.normals[i], mesh.tangents.empty() ? glm::vec4(1, 0, 0, 1) : mesh.tangents[i],
                   mesh.uvs[i]};
  GpuMesh g;
  g.vertices = gl::make_buffer(static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data());
  g.indices = gl::make_buffer(static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data());
  g.index_count = static_cast<GLsizei>(mesh.indices.size());
  g.transform = transform;
  g.material = material;
  g.vao = gl::make_vertex_array();
  const GLuint vao = g.vao.id();
  glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, g.indices.id());
  const GLuint sizes[] = {3, 3, 4, 2};
  const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, tangent),
                            offsetof(Vertex, uv)};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, static_cast<GLint>(sizes[a]), GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  return g;
}

LightGpu to_gpu(const Light& l) {
  LightGpu g{};
  g.colour_type = glm::vec4(l.colour, static_cast<float>(gpu_light_kind(l)));
  g.position_radius = glm::vec4(l.position, l.radius);
  // Sun cones in double: 1 - cos = 2 sin^2(theta / 2) keeps its precision at small angles, where
  // 1 - cos in float would not (shaders/common/lights.glsl, sunOneMinusCos).
  const double theta = static_cast<double>(l.angular_radius_degrees) * (3.14159265358979323846 / 180.0);
  const double half_sin = std::sin(0.5 * theta);
  g.direction_cos = glm::vec4(l.direction, static_cast<float>(std::cos(theta)));
  if (l.type == LightType::Quad) {
    const glm::vec3 u = glm::normalize(glm::cross(l.up, l.direction));
    const glm::vec3 v = glm::cross(l.direction, u);
    g.axis_u = glm::vec4(0.5f * l.size.x * u, 0.0f);
    g.axis_v = glm::vec4(0.5f * l.size.y * v, 0.0f);
  }
  g.axis_u.w = static_cast<float>(2.0 * half_sin * half_sin);
  return g;
}

/// A repeating, trilinearly filtered float texture with a full mip chain averaged from level 0.
gl::Texture make_mipmapped_texture(GLenum format, GLenum channels, int width, int height, const float* texels) {
  gl::Texture tex = gl::make_texture(GL_TEXTURE_2D);
  int levels = 1;
  for (int s = std::max(width, height); s > 1; s /= 2) ++levels;
  glTextureStorage2D(tex.id(), levels, format, width, height);
  glTextureSubImage2D(tex.id(), 0, 0, 0, width, height, channels, GL_FLOAT, texels);
  glGenerateTextureMipmap(tex.id());
  glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return tex;
}

/// Rotation taking +y to `n` (the generators build disks and planes facing +y).
glm::mat4 orient_y_to(glm::vec3 n, glm::vec3 up_hint) {
  glm::vec3 x = glm::cross(up_hint, n);
  if (glm::length(x) < 1e-6f) x = glm::cross(glm::vec3(1, 0, 0), n);
  if (glm::length(x) < 1e-6f) x = glm::cross(glm::vec3(0, 0, 1), n);
  x = glm::normalize(x);
  const glm::vec3 z = glm::cross(x, n);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x, 0);
  m[1] = glm::vec4(n, 0);
  m[2] = glm::vec4(z, 0);
  return m;
}

}  // namespace

GpuScene::NormalMapTextures GpuScene::upload_normal_map(const NormalMap& map) {
  const std::size_t n = map.normals.size();
  std::vector<glm::vec4> normals(n), moments(n);
  std::vector<float> cross(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 v = map.normals[i];
    const glm::vec2 b = glm::vec2(v) / std::max(v.z, 1e-3f);  // slopes; maps keep n.z > 0
    normals[i] = glm::vec4(v, 1.0f);
    moments[i] = glm::vec4(b, b * b);
    cross[i] = b.x * b.y;
  }
  NormalMapTextures t;
  t.normals = make_mipmapped_texture(GL_RGBA32F, GL_RGBA, map.width, map.height, &normals[0].x);
  t.slope_moments = make_mipmapped_texture(GL_RGBA32F, GL_RGBA, map.width, map.height, &moments[0].x);
  t.slope_cross_moment = make_mipmapped_texture(GL_R32F, GL_RED, map.width, map.height, cross.data());
  return t;
}

GpuScene::GpuScene(const Scene& scene, TableCache tables) : tables_(std::move(tables)) {
  for (const auto& shape : scene.shapes) meshes_.push_back(upload(*shape.mesh, shape.transform, shape.material));

  std::vector<MaterialGpu> materials;
  for (const auto& m : scene.materials) {
    const GlintParams g = m.glints.value_or(GlintParams{});
    materials.push_back({glm::vec4(m.f0, m.ndf == Ndf::Beckmann ? 1.0f : 0.0f), glm::vec4(m.diffuse, m.normal_map_tiling),
                         glm::vec4(m.alpha, m.rho, 0.0f),
                         glm::vec4(g.log_density, g.relative_area, g.max_anisotropy, 0.0f)});
    normal_maps_.push_back(m.normal_map ? upload_normal_map(*m.normal_map) : NormalMapTextures{});
    glinty_.push_back(m.glints.has_value());
  }
  for (const auto& m : scene.materials)
    for (const auto& id : material_tables(m))
      if (std::find(material_table_ids_.begin(), material_table_ids_.end(), id) == material_table_ids_.end())
        material_table_ids_.push_back(id);
  std::sort(material_table_ids_.begin(), material_table_ids_.end());
  tables_.require(material_table_ids_);
  materials.resize(kMaxMaterials);  // the uniform block's declared size
  materials_ = gl::make_buffer(static_cast<GLsizeiptr>(materials.size() * sizeof(MaterialGpu)), materials.data());

  // Sorted by kind, in the scene's order within a kind (shaders/common/light_loop.glsl).
  std::vector<LightGpu> lights;
  for (int kind = 0; kind < kLightKindCount; ++kind) {
    const int begin = static_cast<int>(lights.size());
    for (const auto& l : scene.lights)
      if (static_cast<int>(gpu_light_kind(l)) == kind) lights.push_back(to_gpu(l));
    light_ranges_[static_cast<std::size_t>(kind)] = glm::ivec2(begin, static_cast<int>(lights.size()));
  }
  for (const auto& l : scene.lights) {
    if (!l.is_area() || !l.visible) continue;
    GpuEmitter e;
    e.radiance = l.colour;
    if (l.type == LightType::Sphere) {
      e.mesh = upload(make_sphere(l.radius, 48, 24), glm::translate(glm::mat4(1.0f), l.position), 0);
      e.two_sided = true;
    } else {
      const Mesh m = l.type == LightType::Disk ? make_disk(l.radius, 96) : make_plane(l.size, 1.0f);
      e.mesh = upload(m, glm::translate(glm::mat4(1.0f), l.position) * orient_y_to(l.direction, l.up), 0);
    }
    emitters_.push_back(std::move(e));
  }
  lights.resize(kMaxLights);  // the uniform block's declared size
  lights_ = gl::make_buffer(static_cast<GLsizeiptr>(lights.size() * sizeof(LightGpu)), lights.data());
  check_gl("uploading the scene");
}

void GpuScene::bind_buffers() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, lights_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 2, materials_.id());
}

}  // namespace glintlab
