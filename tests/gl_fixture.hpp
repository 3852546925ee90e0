#pragma once
// Shared GL state for tests: one headless context per test binary, and helpers to render a scene
// (a TestScene or a loaded one), and to evaluate GLSL functions on the device through a compute shader.
#include <epoxy/gl.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/reference_backend.hpp"
#include "render/renderer.hpp"
#include "tables/registry.hpp"
#include "render/shader_contract.hpp"
#include "scene/scene_loader.hpp"
#include "shading/registry.hpp"
#include "test_scenes.hpp"

namespace glintlab::test {

inline GlContext& context() {
  static std::unique_ptr<GlContext> ctx = GlContext::create_headless();
  return *ctx;
}

inline ShaderLibrary& shaders() {
  context();
  static ShaderLibrary lib(choose_driver_profile(context()));
  static const bool generated = (add_contract_sources(lib), true);  // generated/*.glsl (shader_contract.hpp)
  (void)generated;
  return lib;
}

/// The precomputed tables' cache of the test binaries: in the build tree (never the user's cache
/// directory), shared by the test processes (entries are written atomically).
inline TableCache test_table_cache() { return TableCache(GLINTLAB_TEST_TABLE_CACHE); }

/// A scene on the GPU with its renderer.
struct SceneFixture {
  explicit SceneFixture(Scene s) : scene(std::move(s)) {
    context();
    gpu = std::make_unique<GpuScene>(scene, test_table_cache());
    renderer = std::make_unique<Renderer>(shaders(), *gpu);
    reference_backend = make_reference_backend("raster", {shaders(), *gpu, *renderer});
  }
  explicit SceneFixture(const TestScene& s) : SceneFixture(s.scene()) {}
  /// The scene's camera and film rendered by a method, parameters as `--param` gives them.
  Frame method(const std::string& id, const std::map<std::string, std::string>& params = {}) {
    const auto& m = find_method(id);
    return renderer->render(m, resolve_params(m, params), scene.camera, scene.film.width, scene.film.height);
  }
  /// The scene's ground truth (its mean), `spp` samples per pixel.
  Frame reference(int spp, int light_samples = 0) { return reference_estimate(spp, light_samples).mean; }
  /// The same with its own error (standard error, passes); `seed` as a frame's.
  ReferenceFrame reference_estimate(int spp, int light_samples = 0, int seed = 0) {
    ReferenceSettings s;
    s.spp = spp;
    s.light_samples = light_samples;
    s.seed = seed;
    return reference_at(scene.camera, scene.film.width, scene.film.height, s);
  }
  /// Ground truth of any view of the scene.
  ReferenceFrame reference_at(const Camera& camera, int width, int height, const ReferenceSettings& settings) {
    return render_reference(*reference_backend, camera, width, height, settings);
  }
  Scene scene;
  std::unique_ptr<GpuScene> gpu;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<ReferenceBackend> reference_backend;
};

/// Runs `body` (GLSL defining `vec4 evaluate(vec4 a, vec4 b)`, after `includes`) on every pair
/// of inputs on the GL device and returns the results. `includes` may read a table bound with
/// GpuTables::bind (its unit comes from generated/gpu_contract.glsl).
inline std::vector<glm::vec4> evaluate_glsl(const std::string& includes, const std::string& body,
                                            const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  static int counter = 0;
  const std::string path = "test/harness" + std::to_string(counter++) + ".comp";
  shaders().add_source(path, "layout(local_size_x = 64) in;\n" + includes + "\n" + body + R"(
layout(std430, binding = 5) readonly buffer InA { vec4 inA[]; };
layout(std430, binding = 6) readonly buffer InB { vec4 inB[]; };
layout(std430, binding = 7) writeonly buffer Out { vec4 outV[]; };
uniform uint uCount;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uCount) outV[i] = evaluate(inA[i], inB[i]);
}
)");
  const GLuint program = shaders().compute(path);
  const auto bytes = static_cast<GLsizeiptr>(a.size() * sizeof(glm::vec4));
  gl::Buffer ba = gl::make_buffer(bytes, a.data()), bb = gl::make_buffer(bytes, b.data());
  gl::Buffer out = gl::make_buffer(bytes, nullptr, GL_MAP_READ_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, ba.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, bb.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, out.id());
  glUseProgram(program);
  glProgramUniform1ui(program, glGetUniformLocation(program, "uCount"), static_cast<GLuint>(a.size()));
  glDispatchCompute(static_cast<GLuint>((a.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> result(a.size());
  glGetNamedBufferSubData(out.id(), 0, bytes, result.data());
  check_gl("evaluating GLSL");
  return result;
}

}  // namespace glintlab::test
