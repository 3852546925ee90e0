#include "render/renderer.hpp"

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <set>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "gl/context.hpp"
#include "render/shader_contract.hpp"

namespace glintlab {

int ReferenceSettings::subpixels() const {
  for (int k = 32; k > 1; --k)
    if (spp % (k * k) == 0 && 4 * k * k <= spp) return k;
  return 1;
}

int ReferenceSettings::effective_light_samples() const {
  return light_samples > 0 ? light_samples : std::max(1, (256 + spp - 1) / spp);
}

void validate_spp(int spp) {
  if (spp < 1 || spp > kMaxReferenceSpp)
    throw InputError("--spp " + std::to_string(spp) + ": allowed: 1 .. " + std::to_string(kMaxReferenceSpp) +
                     " samples per pixel (best 4 k^2: 64, 256, 1024, 4096)");
}

Renderer::Renderer(ShaderLibrary& shaders, const GpuScene& scene) : shaders_(shaders), scene_(scene) {
  add_contract_sources(shaders_);
  frame_ubo_ = gl::make_buffer(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

RenderTarget& Renderer::target(int width, int height) {
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<RenderTarget>(width, height);
  return *target_;
}

namespace {

/// The reference's shading module: it reads every texture unfiltered (REFERENCE_PASS).
constexpr const char* kReferenceModule = "passes/reference.glsl";

/// A well-mixed 32-bit hash (the finaliser of MurmurHash3) for per-pass seeds and jitter.
std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x85ebca6bu;
  x ^= x >> 13;
  x *= 0xc2b2ae35u;
  x ^= x >> 16;
  return x;
}

float unit_float(std::uint32_t x) { return static_cast<float>(x >> 8) * (1.0f / 16777216.0f); }

}  // namespace

ShaderDefines forward_variant(const std::string& module, const LightRanges& light_ranges, MaterialVariant material) {
  std::string ranges = "ivec2[](";
  for (std::size_t k = 0; k < light_ranges.size(); ++k)
    ranges += (k ? ", ivec2(" : "ivec2(") + std::to_string(light_ranges[k].x) + ", " + std::to_string(light_ranges[k].y) + ")";
  return {{"$METHOD", module},
          {"LIGHT_RANGES", ranges + ")"},
          {"MATERIAL_NORMAL_MAP", material.normal_map ? "1" : "0"},
          {"MATERIAL_GLINTS", material.glints ? "1" : "0"},
          {"REFERENCE_PASS", module == kReferenceModule ? "1" : "0"}};
}

GLuint Renderer::forward_program(const std::string& module, int material) {
  const MaterialVariant variant{scene_.normal_map(material) != 0, scene_.glinty(material)};
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
      for (const auto& [name, value] : params) {
        const GLint loc = glGetUniformLocation(program, ("param_" + name).c_str());
        if (loc >= 0) glProgramUniform1f(program, loc, value);
      }
    }
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(mesh.transform));
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uModel"), 1, GL_FALSE, &mesh.transform[0][0]);
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, &normal_matrix[0][0]);
    glProgramUniform1i(program, glGetUniformLocation(program, "uMaterial"), mesh.material);
    glBindTextureUnit(kNormalMapUnit, scene_.normal_map(mesh.material));
    glBindTextureUnit(kSlopeMomentsUnit, scene_.slope_moments(mesh.material));
    glBindTextureUnit(kSlopeCrossMomentUnit, scene_.slope_cross_moment(mesh.material));
    glBindTextureUnit(kGlintDictionaryUnit, scene_.glint_dictionary().texture.id());
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
  glBindVertexArray(0);
  check_gl("drawing the scene");
}

Renderer::FrameUniforms Renderer::frame_uniforms(const Camera& camera, const glm::mat4& projection, glm::ivec4 target,
                                                 glm::ivec4 tile) const {
  FrameUniforms f{};
  f.view_proj = projection * camera.view_matrix();
  f.camera_pos = {camera.position, camera.projection == Projection::Perspective ? 1.0f : 0.0f};
  f.camera_forward = glm::vec4(glm::normalize(camera.target - camera.position), 0.0f);
  f.target = target;
  f.tile = tile;
  return f;
}

void Renderer::draw(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height) {
  draw_module(method.module_path(), params, camera, width, height);
}

void Renderer::draw_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                           int height) {
  RenderTarget& rt = target(width, height);
  rt.bind_and_clear();
  draw_scene(module, params,
             frame_uniforms(camera, camera.projection_matrix(static_cast<float>(width) / static_cast<float>(height)),
                            {width, height, 1, 0}, {0, 0, 1, 0}));
}

Frame Renderer::render(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height) {
  return render_module(method.module_path(), params, camera, width, height);
}

Frame Renderer::render_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                              int height) {
  draw_module(module, params, camera, width, height);
  return {RenderTarget::read(target_->total(), width, height), RenderTarget::read(target_->specular(), width, height)};
}

ReferenceFrame Renderer::render_reference(const Camera& camera, int width, int height,
                                          const ReferenceSettings& settings, const ProgressFn& progress) {
  validate_spp(settings.spp);
  const int k = settings.subpixels(), passes = settings.passes();
  ReferenceAccumulator accumulator(width, height, k * k);
  for (int p = 0; p < passes; ++p) {
    accumulator.add_pass(render_reference_pass(
        camera, width, height, k, settings.effective_light_samples(), reference_pass_seed(settings.seed, p),
        reference_pass_jitter(settings.seed, p), [&](int done, int total) {
          if (progress) progress(p * total + done, passes * total);
        }));
  }
  return accumulator.result();
}

std::uint64_t Renderer::reference_program_hash() const {
  Hasher h;
  std::set<MaterialVariant> variants;
  for (const auto& mesh : scene_.meshes())
    variants.insert({scene_.normal_map(mesh.material) != 0, scene_.glinty(mesh.material)});
  for (const MaterialVariant& v : variants) {
    const ShaderDefines defines = forward_variant(kReferenceModule, scene_.light_ranges(), v);
    h.text(shaders_.expand("passes/forward.vert", defines));
    h.text(shaders_.expand("passes/forward.frag", defines));
  }
  h.text(shaders_.expand("passes/emitter.frag", {}));
  h.text(shaders_.expand("passes/downsample.comp", {}));
  return h.digest();
}

std::uint32_t reference_pass_seed(int frame_seed, int pass) {
  return mix32(static_cast<std::uint32_t>(frame_seed) * 0x9e3779b9u ^ mix32(static_cast<std::uint32_t>(pass) + 1u));
}

glm::vec2 reference_pass_jitter(int frame_seed, int pass) {
  const std::uint32_t h = mix32(reference_pass_seed(frame_seed, pass) ^ 0x6a09e667u);
  return {unit_float(h), unit_float(mix32(h))};
}

Frame Renderer::render_reference_pass(const Camera& camera, int width, int height, int k, int light_samples,
                                      std::uint32_t seed, glm::vec2 jitter, const ProgressFn& progress) {
  if (k < 1 || k > 32) throw InputError("reference sub-pixels per axis " + std::to_string(k) + ": allowed: 1 .. 32");
  constexpr int kMaxTileSide = 2048;  // sub-pixels per side of one high-resolution tile
  const int tile = std::max(1, kMaxTileSide / k);
  const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;

  RenderTarget high(std::min(width, tile) * k, std::min(height, tile) * k);
  gl::Texture out_total = gl::make_texture(GL_TEXTURE_2D), out_specular = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(out_total.id(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(out_specular.id(), 1, GL_RGBA32F, width, height);

  const GLuint downsample = shaders_.compute("passes/downsample.comp");
  const glm::ivec2 film(width, height);
  int done = 0;
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      // Tile in output pixels, y down (film convention).
      const glm::ivec2 origin(tx * tile, ty * tile);
      const glm::ivec2 size(std::min(tile, width - origin.x), std::min(tile, height - origin.y));
      const int gl_y = height - origin.y - size.y;  // the same tile in GL's y-up pixel rows
      const glm::ivec2 high_size = size * k;
      // The rasteriser samples each sub-pixel at its centre; moving the image by (0.5 - jitter)
      // sub-pixels makes that centre see the point `jitter` from the cell's corner instead.
      const glm::vec2 shift_ndc = 2.0f * (glm::vec2(0.5f) - jitter) / glm::vec2(high_size);
      const glm::mat4 projection = glm::translate(glm::mat4(1.0f), glm::vec3(shift_ndc, 0.0f)) *
                                   camera.tile_projection_matrix(film, origin, size);
      high.bind_and_clear(high_size.x, high_size.y);
      draw_scene(kReferenceModule, {},
                 frame_uniforms(camera, projection, {high_size.x, high_size.y, k, 0},
                                {origin.x * k, gl_y * k, light_samples, static_cast<int>(seed & 0x7fffffffu)}));

      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
      glUseProgram(downsample);
      glBindImageTexture(0, high.total(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
      glBindImageTexture(1, high.specular(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
      glBindImageTexture(2, out_total.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      glBindImageTexture(3, out_specular.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      glProgramUniform1i(downsample, glGetUniformLocation(downsample, "uSubpixels"), k);
      glProgramUniform2i(downsample, glGetUniformLocation(downsample, "uTileSize"), size.x, size.y);
      glProgramUniform2i(downsample, glGetUniformLocation(downsample, "uOutOrigin"), origin.x, gl_y);
      glDispatchCompute(static_cast<GLuint>((size.x + 7) / 8), static_cast<GLuint>((size.y + 7) / 8), 1);
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
      glFinish();  // one tile at a time keeps progress honest and the driver's queue short
      check_gl("rendering a reference tile");
      if (progress) progress(++done, tiles_x * tiles_y);
    }
  return {RenderTarget::read(out_total.id(), width, height), RenderTarget::read(out_specular.id(), width, height)};
}

}  // namespace glintlab
