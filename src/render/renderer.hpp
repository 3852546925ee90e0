#pragma once
// The forward renderer: draws a GpuScene with one method's module, or with the reference
// estimator at k x k sub-pixels per pixel in tiles (ground truth). Knows no method by name.
#include <functional>
#include <memory>

#include "core/image.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/render_target.hpp"
#include "scene/camera.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// One rendered frame: linear radiance and its specular part.
struct Frame {
  Image total;
  Image specular;
};

struct ReferenceSettings {
  int spp = 64;            ///< k * k sub-pixels per pixel, k in 1..32
  int light_samples = 0;   ///< per sub-pixel and light with extent; 0: max(1, ceil(256 / spp))
  int seed = 0;            ///< decorrelates frames of an animation
  [[nodiscard]] int subpixels() const;
  [[nodiscard]] int effective_light_samples() const;
};

/// Throws InputError unless spp is k*k with k in 1..32.
void validate_spp(int spp);

/// Called after each reference tile: (tiles done, tiles total).
using ProgressFn = std::function<void(int, int)>;

class Renderer {
 public:
  Renderer(ShaderLibrary& shaders, const GpuScene& scene);

  /// Renders with a method; `params` must hold every declared parameter.
  Frame render(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// Issues the draws of render() into the internal target without reading back (for timing).
  void draw(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// Ground truth: k x k supersampling in tiles, box-filtered (DESIGN.md, "Ground truth").
  Frame render_reference(const Camera& camera, int width, int height, const ReferenceSettings& settings,
                         const ProgressFn& progress = {});

 private:
  struct FrameUniforms;
  FrameUniforms frame_uniforms(const Camera& camera, const glm::mat4& projection, glm::ivec4 target,
                               glm::ivec4 tile) const;
  void draw_scene(GLuint program, const FrameUniforms& frame);
  GLuint method_program(const MethodDescriptor& method);
  RenderTarget& target(int width, int height);

  ShaderLibrary& shaders_;
  const GpuScene& scene_;
  gl::Buffer frame_ubo_;
  std::unique_ptr<RenderTarget> target_;
};

}  // namespace glintlab
