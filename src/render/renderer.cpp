#include "render/renderer.hpp"

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include "core/error.hpp"
#include "gl/context.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"
#include "tables/registry.hpp"
#include "shading/method_module.hpp"

namespace glintlab {

Renderer::Renderer(ShaderLibrary& shaders, const GpuScene& scene) : shaders_(shaders), scene_(scene) {
  add_contract_sources(shaders_);
  frame_ubo_ = gl::make_buffer(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
  empty_vertex_array_ = gl::make_vertex_array();
}

RenderTarget& Renderer::target(int width, int height) {
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<RenderTarget>(width, height);
  return *target_;
}

namespace {
/// The GL type of an active uniform of `program` (GL_FLOAT, GL_INT, ...).
GLint uniform_type(GLuint program, const std::string& name) {
  const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
  const GLenum property = GL_TYPE;
  GLint type = 0;
  if (index != GL_INVALID_INDEX) glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr, &type);
  return type;
}
}  // namespace

void set_param_uniforms(GLuint program, const ParamValues& params) {
  for (const auto& [name, value] : params) {
    // Every parameter is read by the module (method_program_module checked), but a variant may
    // not use it (a glint parameter on a material without glints): then it has no location.
    const std::string uniform = "param_" + name;
    const GLint loc = glGetUniformLocation(program, uniform.c_str());
    if (loc < 0) continue;
    // An enumeration is a `uniform int`, the choice's index (shading/method_module.hpp).
    if (uniform_type(program, uniform) == GL_INT)
      glProgramUniform1i(program, loc, static_cast<GLint>(std::lround(value)));
    else
      glProgramUniform1f(program, loc, value);
  }
}

ShaderDefines forward_variant(const std::string& module, const LightRanges& light_ranges, MaterialVariant material) {
  std::string ranges = "ivec2[](";
  for (std::size_t k = 0; k < light_ranges.size(); ++k)
    ranges += (k ? ", ivec2(" : "ivec2(") + std::to_string(light_ranges[k].x) + ", " + std::to_string(light_ranges[k].y) + ")";
  const MaterialKind& kind = all_material_kinds().at(static_cast<std::size_t>(material.kind));
  ShaderDefines defines = {{"$METHOD", module},
          {"$MATERIAL", material_kind_module(kind)},
          {"LIGHT_RANGES", ranges + ")"},
          {"MATERIAL_KIND", std::to_string(kind.code())},  // compare with MATERIAL_KIND_<ID> (the contract)
          {"MATERIAL_NORMAL_MAP", material.normal_map ? "1" : "0"},
          {"MATERIAL_TEXTURES", material.textures ? "1" : "0"},
          {"MATERIAL_ANISOTROPIC", material.anisotropic ? "1" : "0"},
          {"MATERIAL_WANG_TILES", material.wang_tiles ? "1" : "0"},
          {"REFERENCE_PASS", is_reference_module(module) ? "1" : "0"},
          {"REFERENCE_SURFACE", std::to_string(static_cast<int>(reference_surface(module)))}};
  for (std::size_t k = 0; k < light_ranges.size(); ++k)
    defines.emplace_back(light_count_define(all_light_kinds().at(k)), std::to_string(light_ranges[k].y - light_ranges[k].x));
  if (const MethodDescriptor* method = method_of_generated_module(module))
    for (const std::string& id : method->light_kinds_built) defines.emplace_back(light_built_define(find_light_kind(id)), "1");
  return defines;
}

MaterialVariant material_variant(const GpuScene& scene, int material) {
  return {scene.kind(material).code(), scene.normal_map(material) != 0, scene.textured(material),
          scene.anisotropic(material), scene.wang_tiled(material)};
}

std::string method_program_module(ShaderLibrary& shaders, const MethodDescriptor& method, const ParamValues& params) {
  const std::string path = generated_module_path(method, params);
  if (!shaders.exists(path))
    shaders.add_source(path, generated_module_source(method, shaders.source(method.module_path()), params));
  return path;
}

GLuint Renderer::forward_program(const std::string& module, int material) {
  const MaterialVariant variant = material_variant(scene_, material);
  GLuint& program = forward_programs_[{module, variant}];
  if (!program)
    program = shaders_.graphics("passes/forward.vert", "passes/forward.frag",
                                forward_variant(module, scene_.light_ranges(), variant));
  return program;
}

void Renderer::draw_scene(const std::string& module, const ParamValues& params, const FrameUniforms& frame) {
  glNamedBufferSubData(frame_ubo_.id(), 0, sizeof(FrameUniforms), &frame);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frame_ubo_.id());
  scene_.bind_buffers();
  // What the scene's kinds read, then what the method prepare() was last called for reads (bound
  // for any module: a pass that reads none of it is not affected).
  scene_.resources().bind(scene_.scene_resource_ids(), scene_.resource_context());
  scene_.resources().bind(method_resources_, scene_.resource_context(method_params_));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);

  GLuint program = 0;
  for (const auto& mesh : scene_.meshes()) {
    const GLuint variant = forward_program(module, mesh.material);
    if (variant != program) {
      program = variant;
      glUseProgram(program);
      set_param_uniforms(program, params);
    }
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(mesh.transform));
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uModel"), 1, GL_FALSE, &mesh.transform[0][0]);
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, &normal_matrix[0][0]);
    scene_.bind_material(program, mesh.material);
    glBindVertexArray(mesh.vao.id());
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
  }

  const GLuint emitter = shaders_.graphics("passes/forward.vert", "passes/emitter.frag");
  glUseProgram(emitter);
  for (const auto& e : scene_.emitters()) {
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(e.mesh.transform));
    glProgramUniformMatrix4fv(emitter, glGetUniformLocation(emitter, "uModel"), 1, GL_FALSE, &e.mesh.transform[0][0]);
    glProgramUniformMatrix3fv(emitter, glGetUniformLocation(emitter, "uNormalMatrix"), 1, GL_FALSE, &normal_matrix[0][0]);
    glProgramUniform3fv(emitter, glGetUniformLocation(emitter, "uRadiance"), 1, &e.radiance[0]);
    glProgramUniform1i(emitter, glGetUniformLocation(emitter, "uTwoSided"), e.two_sided ? 1 : 0);
    glBindVertexArray(e.mesh.vao.id());
    glDrawElements(GL_TRIANGLES, e.mesh.index_count, GL_UNSIGNED_INT, nullptr);
  }
  if (scene_.background_light() >= 0) {
    // Where nothing was drawn (depth still 1), the environment (shaders/passes/background.frag).
    const GLuint background = shaders_.graphics("passes/background.vert", "passes/background.frag");
    glUseProgram(background);
    glProgramUniform1i(background, glGetUniformLocation(background, "uLight"), scene_.background_light());
    const glm::mat4 clip_to_world = glm::inverse(frame.view_proj);
    glProgramUniformMatrix4fv(background, glGetUniformLocation(background, "uClipToWorld"), 1, GL_FALSE,
                              &clip_to_world[0][0]);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glBindVertexArray(empty_vertex_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
  }
  glBindVertexArray(0);
  check_gl("drawing the scene");
}

FrameUniforms frame_uniforms(const Camera& camera, const glm::mat4& projection, glm::ivec4 target, glm::ivec4 tile) {
  FrameUniforms f{};
  f.view_proj = projection * camera.view_matrix();
  f.camera_pos = {camera.position, camera.projection == Projection::Perspective ? 1.0f : 0.0f};
  f.camera_forward = glm::vec4(glm::normalize(camera.target - camera.position), 0.0f);
  f.target = target;
  f.target.w = 0;  // the hardware profile's rolled light loops add it to their counts (lights/light_loop.glsl)
  f.tile = tile;
  return f;
}

void Renderer::prepare(const MethodDescriptor& method, const ParamValues& params) {
  method_resources_ = method_resources(method, params);
  method_params_ = params;
  scene_.resources().require(method_resources_, scene_.resource_context(method_params_));
}

void Renderer::draw(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height) {
  prepare(method, params);
  draw_module(method_program_module(shaders_, method, params), params, camera, width, height);
}

void Renderer::draw_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                           int height) {
  draw_module(module, params, camera, target(width, height));
}

void Renderer::draw_module(const std::string& module, const ParamValues& params, const Camera& camera,
                           RenderTarget& target) {
  const int width = target.width(), height = target.height();
  target.bind_and_clear();
  draw_scene(module, params,
             frame_uniforms(camera, camera.projection_matrix(static_cast<float>(width) / static_cast<float>(height)),
                            {width, height, 1, 0}, {0, 0, 1, 0}));
}

void Renderer::draw_view(const std::string& module, const ParamValues& params, const Camera& camera,
                         const glm::mat4& projection, glm::ivec4 target, glm::ivec4 tile) {
  draw_scene(module, params, frame_uniforms(camera, projection, target, tile));
}

Frame Renderer::render(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height) {
  prepare(method, params);
  return render_module(method_program_module(shaders_, method, params), params, camera, width, height);
}

Frame Renderer::render_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                              int height) {
  draw_module(module, params, camera, width, height);
  return read_frame();
}

Frame Renderer::read_frame() const {
  if (!target_) throw RuntimeFailure("Renderer::read_frame: nothing has been drawn yet");
  const int w = target_->width(), h = target_->height();
  return {RenderTarget::read(target_->total(), w, h), RenderTarget::read(target_->specular(), w, h)};
}

}  // namespace glintlab
