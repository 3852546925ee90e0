#include "render/gpu_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>

#include "core/gpu_contract.hpp"
#include "gl/context.hpp"

namespace glintlab {

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 tangent;
  glm::vec2 uv;
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

/// A material's affine uv map as the column-major mat3x2 GLSL reads: columns x, y and the offset.
void store_transform(const glm::mat3& m, float* out) {
  for (int c = 0; c < 3; ++c) {
    out[2 * c] = m[c][0];
    out[2 * c + 1] = m[c][1];
  }
}

}  // namespace

GLuint GpuScene::upload_texture(const std::shared_ptr<const MaterialTexture>& texture) {
  if (!texture) return white_.id();
  auto it = texture_objects_.find(texture.get());
  if (it != texture_objects_.end()) return it->second.id();
  const MaterialTexture& t = *texture;
  gl::Texture tex = gl::make_texture(GL_TEXTURE_2D);
  int levels = 1;
  for (int s = std::max(t.width, t.height); s > 1; s /= 2) ++levels;
  glTextureStorage2D(tex.id(), levels, t.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, t.width, t.height);
  glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
  glGenerateTextureMipmap(tex.id());
  glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  const GLuint id = tex.id();
  texture_objects_.emplace(texture.get(), std::move(tex));
  return id;
}

GpuScene::MaterialTextures GpuScene::material_textures(const Material& m) {
  MaterialTextures t;
  // The normal map's coordinates: its tiling, then the texture transform.
  store_transform(m.normal_map_transform * glm::mat3(glm::vec3(m.normal_map_tiling, 0, 0),
                                                     glm::vec3(0, m.normal_map_tiling, 0), glm::vec3(0, 0, 1)),
                  &t.transforms[6 * kTextureSlotNormalMap]);
  store_transform(glm::mat3(1.0f), &t.transforms[6 * kTextureSlotBaseColor]);
  store_transform(glm::mat3(1.0f), &t.transforms[6 * kTextureSlotMetallicRoughness]);
  store_transform(glm::mat3(1.0f), &t.transforms[6 * kTextureSlotEmissive]);
  if (!m.textures) return t;
  const TexturedMetalRough& x = *m.textures;
  t.textured = true;
  t.base_color = upload_texture(x.base_color_texture.texture);
  t.metallic_roughness = upload_texture(x.metallic_roughness_texture.texture);
  t.emissive = upload_texture(x.emissive_texture.texture);
  store_transform(x.base_color_texture.transform, &t.transforms[6 * kTextureSlotBaseColor]);
  store_transform(x.metallic_roughness_texture.transform, &t.transforms[6 * kTextureSlotMetallicRoughness]);
  store_transform(x.emissive_texture.transform, &t.transforms[6 * kTextureSlotEmissive]);
  return t;
}

void GpuScene::bind_material(GLuint program, int material) const {
  const MaterialTextures& t = textures_[index(material)];
  glProgramUniform1i(program, glGetUniformLocation(program, "uMaterial"), material);
  glProgramUniformMatrix3x2fv(program, glGetUniformLocation(program, "uTextureTransforms"), kTextureSlots, GL_FALSE,
                              t.transforms.data());
  glBindTextureUnit(kNormalMapUnit, normal_map(material));
  glBindTextureUnit(kSlopeMomentsUnit, slope_moments(material));
  glBindTextureUnit(kSlopeCrossMomentUnit, slope_cross_moment(material));
  glBindTextureUnit(kBaseColorUnit, t.textured ? t.base_color : 0);
  glBindTextureUnit(kMetallicRoughnessUnit, t.textured ? t.metallic_roughness : 0);
  glBindTextureUnit(kEmissiveUnit, t.textured ? t.emissive : 0);
}

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

LightGpu pack_light(const Light& l) {
  LightGpu g = l.kind->pack(l);
  g.colour_type.w = static_cast<float>(l.kind->code());
  return g;
}

MaterialGpu pack_material(const Material& m) {
  const TexturedMetalRough x = m.textures.value_or(TexturedMetalRough{});
  const float ndf = static_cast<float>(m.ndf == Ndf::Beckmann ? kNdfBeckmann : kNdfGgx);
  return {glm::vec4(m.f0, ndf), glm::vec4(m.diffuse, m.normal_map_tiling),
          glm::vec4(m.alpha, m.rho, m.anisotropy_rotation),
          glm::vec4(m.kind_params[0], m.kind_params[1], m.kind_params[2], m.kind_params[3]),
          glm::vec4(m.emission, 0.0f),
          x.base_color, glm::vec4(x.metallic, x.roughness, x.anisotropy, 0.0f),
          glm::vec4(x.dielectric_f0, 0.0f)};
}

GpuScene::GpuScene(const Scene& scene, TableCache tables)
    : scene_(scene), resources_(std::move(tables)), scene_resource_ids_(scene_resources(scene)) {
  for (const auto& shape : scene.shapes) meshes_.push_back(upload(*shape.mesh, shape.transform, shape.material));

  white_ = gl::make_texture(GL_TEXTURE_2D);
  const std::uint8_t white[4] = {255, 255, 255, 255};
  glTextureStorage2D(white_.id(), 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(white_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);

  std::vector<MaterialGpu> materials;
  for (const auto& m : scene.materials) {
    materials.push_back(pack_material(m));
    normal_maps_.push_back(m.normal_map ? upload_normal_map(*m.normal_map) : NormalMapTextures{});
    kinds_.push_back(m.kind);
    textures_.push_back(material_textures(m));
    anisotropic_.push_back(m.anisotropic());
  }
  resources_.require(scene_resource_ids_, resource_context());
  materials.resize(kMaxMaterials);  // the uniform block's declared size
  materials_ = gl::make_buffer(static_cast<GLsizeiptr>(materials.size() * sizeof(MaterialGpu)), materials.data());

  // Sorted by kind, in the scene's order within a kind (shaders/lights/light_loop.glsl).
  std::vector<LightGpu> lights;
  for (const LightKind& kind : all_light_kinds()) {
    const int begin = static_cast<int>(lights.size());
    for (const auto& l : scene.lights)
      if (l.kind == &kind) {
        if (!kind.compact && l.visible) background_light_ = static_cast<int>(lights.size());
        lights.push_back(pack_light(l));
      }
    light_ranges_.emplace_back(begin, static_cast<int>(lights.size()));
  }
  for (const auto& l : scene.lights) {
    if (!l.kind->emitter) continue;
    std::optional<LightEmitter> shape = l.kind->emitter(l);
    if (!shape) continue;
    GpuEmitter e;
    e.mesh = upload(shape->mesh, shape->transform, 0);
    e.radiance = shape->radiance;
    e.two_sided = shape->two_sided;
    emitters_.push_back(std::move(e));
  }
  lights.resize(kMaxLights);  // the uniform block's declared size
  lights_ = gl::make_buffer(static_cast<GLsizeiptr>(lights.size() * sizeof(LightGpu)), lights.data());
  check_gl("uploading the scene");
}

void GpuScene::bind_buffers() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, kLightBlockBinding, lights_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, kMaterialBlockBinding, materials_.id());
}

}  // namespace glintlab
