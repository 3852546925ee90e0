#pragma once
// The forward renderer: draws a GpuScene with one method's module, or with the reference
// estimator at k x k sub-pixels per pixel in tiles (ground truth). Knows no method by name.
#include <functional>
#include <map>
#include <memory>

#include "core/image.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/reference_estimate.hpp"
#include "render/render_target.hpp"
#include "scene/camera.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// How a reference is sampled: `spp` samples per pixel in all, rendered as passes() independent
/// passes of k x k jittered sub-pixels (k = subpixels()).
struct ReferenceSettings {
  int spp = 64;            ///< passes x k x k; see subpixels()
  int light_samples = 0;   ///< per sub-pixel and light with extent; 0: max(1, ceil(256 / spp))
  int seed = 0;            ///< decorrelates frames of an animation
  /// k: the largest k <= 32 with k * k dividing spp and at most spp / 4 (so that there are at
  /// least four passes to estimate the reference's own error from), or 1.
  [[nodiscard]] int subpixels() const;
  [[nodiscard]] int passes() const { return spp / (subpixels() * subpixels()); }
  [[nodiscard]] int effective_light_samples() const;
};

constexpr int kMaxReferenceSpp = 65536;
/// Throws InputError unless spp is in 1 .. kMaxReferenceSpp.
void validate_spp(int spp);
/// The sample seed and the sub-pixel jitter in [0, 1)^2 of one pass of a frame's reference.
std::uint32_t reference_pass_seed(int frame_seed, int pass);
glm::vec2 reference_pass_jitter(int frame_seed, int pass);

/// What of a material changes the forward program: MATERIAL_NORMAL_MAP and MATERIAL_GLINTS.
struct MaterialVariant {
  bool normal_map = false;
  bool glints = false;
  auto operator<=>(const MaterialVariant&) const = default;
};

/// Defines of one variant of the forward pass (shaders/passes/forward.frag): the shading module
/// (a method's or the reference's), the index range of each light kind in the light buffer and
/// the material's variant.
ShaderDefines forward_variant(const std::string& module, const LightRanges& light_ranges, MaterialVariant material);

/// Called after each reference tile: (tiles done, tiles total).
using ProgressFn = std::function<void(int, int)>;

class Renderer {
 public:
  Renderer(ShaderLibrary& shaders, const GpuScene& scene);

  /// Renders with a method; `params` must hold every declared parameter.
  Frame render(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// Issues the draws of render() into the internal target without reading back (for timing).
  void draw(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// The same with any shading module in the method slot (e.g. passes/unshaded.glsl).
  void draw_module(const std::string& module, const ParamValues& params, const Camera& camera, int width, int height);
  /// draw_module, read back (e.g. the diagnostics of passes/glint_cells.glsl).
  Frame render_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                      int height);
  /// Ground truth (docs/methods.md, "Ground truth"): settings.passes() passes, each of k x k
  /// jittered sub-pixels per pixel, with their mean and standard error.
  ReferenceFrame render_reference(const Camera& camera, int width, int height, const ReferenceSettings& settings,
                                  const ProgressFn& progress = {});
  /// Hash of the full GLSL text of every program the reference runs on this scene (each material's
  /// variant, the emitters, the downsampling): what reference cache keys depend on, so that editing
  /// a method's module does not invalidate cached references.
  [[nodiscard]] std::uint64_t reference_program_hash() const;
  /// One pass of the reference: k x k sub-pixels per pixel, rendered in tiles and box-filtered,
  /// every sub-pixel moved by the same `jitter` in [0, 1)^2 sub-pixels from its cell's corner;
  /// `seed` selects the pass's light and BRDF samples.
  Frame render_reference_pass(const Camera& camera, int width, int height, int subpixels, int light_samples,
                              std::uint32_t seed, glm::vec2 jitter, const ProgressFn& progress = {});

 private:
  using FrameUniforms = glintlab::FrameUniforms;  // std140, src/core/gpu_contract.hpp
  FrameUniforms frame_uniforms(const Camera& camera, const glm::mat4& projection, glm::ivec4 target,
                               glm::ivec4 tile) const;
  /// Draws every shape with `module` (a method's or the reference's) in the forward pass, each
  /// with the program variant for its material, then the visible emitters.
  void draw_scene(const std::string& module, const ParamValues& params, const FrameUniforms& frame);
  /// The forward program for `module`, specialised on the scene's lights and the material;
  /// looked up once per (module, variant), not per draw.
  GLuint forward_program(const std::string& module, int material);
  RenderTarget& target(int width, int height);

  ShaderLibrary& shaders_;
  const GpuScene& scene_;
  gl::Buffer frame_ubo_;
  std::unique_ptr<RenderTarget> target_;
  std::map<std::pair<std::string, MaterialVariant>, GLuint> forward_programs_;
};

}  // namespace glintlab
