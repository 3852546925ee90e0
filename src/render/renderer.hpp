#pragma once
// The forward renderer: draws a GpuScene with one method's module, or with any other shading
// module (the raster reference backend's, diagnostics). Knows no method by name.
#include <map>
#include <memory>

#include "core/gpu_contract.hpp"
#include "core/image.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/reference_estimate.hpp"
#include "render/render_target.hpp"
#include "scene/camera.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// What of a material changes the forward program: its kind (MATERIAL_KIND, and the kind's module
/// in the $MATERIAL slot), MATERIAL_NORMAL_MAP, MATERIAL_TEXTURES, MATERIAL_ANISOTROPIC and MATERIAL_WANG_TILES.
struct MaterialVariant {
  int kind = 0;  ///< the kind's code (MaterialKind::code)
  bool normal_map = false;
  bool textures = false;
  bool anisotropic = false;  ///< Material::anisotropic: an isotropic material's program can skip what only anisotropic lobes need
  bool wang_tiles = false;   ///< its normal map is a surface of Wang tiles (NormalMap::wang): texels read through the lattice
  auto operator<=>(const MaterialVariant&) const = default;
};
MaterialVariant material_variant(const GpuScene& scene, int material);

/// The `raster` reference backend's shading module (src/render/raster_reference.hpp): forward
/// programs built for it read every texture at its base level (REFERENCE_PASS).
inline constexpr const char* kReferenceModule = "passes/reference.glsl";
/// The reference with binomial-glints materials as one fixed microfacet realisation
/// (docs/methods.md#kneiphof2024); every other material as kReferenceModule.
inline constexpr const char* kRealisationReferenceModule = "passes/reference_realisation.glsl";
/// The reference with binomial-glints materials as one fixed field of mirror facets, independent of
/// the counting model (docs/methods.md#kneiphof2024); every other material as kReferenceModule.
inline constexpr const char* kFacetsReferenceModule = "passes/reference_facets.glsl";
/// Is `module` the reference or one of its variants (the passes' REFERENCE_PASS)?
inline bool is_reference_module(const std::string& module) { return module.starts_with("passes/reference"); }
/// The surface a reference module gives stochastic materials (the passes' REFERENCE_SURFACE).
inline ReferenceSurface reference_surface(const std::string& module) {
  if (module == kRealisationReferenceModule) return ReferenceSurface::Realisation;
  if (module == kFacetsReferenceModule) return ReferenceSurface::Facets;
  return ReferenceSurface::Model;
}

/// Defines of one variant of the forward pass (shaders/passes/forward.frag): the shading module
/// (a method's or the reference's), the index range and count of each light kind in the light
/// buffer (and the kinds the method builds lights of itself, MethodDescriptor::light_kinds_built)
/// and the material's variant.
/// The frame block (core/frame.glsl) of a view of `camera` through `projection`: `target` (width,
/// height, sub-pixels per pixel) and `tile` (the region's first sub-pixel, light samples, the pass's
/// seed) as the reference reads them; target.w is left 0 (the hardware profile's rolled loops add it).
FrameUniforms frame_uniforms(const Camera& camera, const glm::mat4& projection, glm::ivec4 target, glm::ivec4 tile);

ShaderDefines forward_variant(const std::string& module, const LightRanges& light_ranges, MaterialVariant material);

/// The module a method's forward program includes in the $METHOD slot: its parameter uniforms,
/// generated from the descriptor, then shaders/methods/<id>.glsl (shading/method_module.hpp).
/// Checks the module's parameters and adds the generated source to `shaders` on first use; throws
/// RuntimeFailure naming the method, the parameter and the module's file.
/// `params` choose the module's compile-time parameters (their defaults where absent).
std::string method_program_module(ShaderLibrary& shaders, const MethodDescriptor& method, const ParamValues& params = {});
/// Sets a method's run-time parameters (the uniforms param_<name>) in `program`, which a module of
/// method_program_module() was compiled into; the parameters it does not read are skipped.
void set_param_uniforms(GLuint program, const ParamValues& params);

class Renderer {
 public:
  Renderer(ShaderLibrary& shaders, const GpuScene& scene);

  /// Renders with a method; `params` must hold every declared parameter.
  Frame render(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// Issues the draws of render() into the internal target without reading back (for timing).
  void draw(const MethodDescriptor& method, const ParamValues& params, const Camera& camera, int width, int height);
  /// Reads back what the last draw or draw_module drew: render() is draw() then read_frame().
  [[nodiscard]] Frame read_frame() const;
  /// The same with any shading module in the method slot (e.g. passes/unshaded.glsl).
  void draw_module(const std::string& module, const ParamValues& params, const Camera& camera, int width, int height);
  /// draw_module into `target` instead of the internal target (the floor's layouts of `glintlab
  /// bench --floor-breakdown`); read_frame() does not see it.
  void draw_module(const std::string& module, const ParamValues& params, const Camera& camera, RenderTarget& target);
  /// draw_module, read back (e.g. the diagnostics of glints/chermain/glint_cells.glsl).
  Frame render_module(const std::string& module, const ParamValues& params, const Camera& camera, int width,
                      int height);

  /// Draws every shape with `module` into the bound target, seen through `projection` (which may
  /// select a jittered tile of the film, as the raster reference does); `target` and `tile` fill
  /// the frame block (shaders/core/frame.glsl).
  void draw_view(const std::string& module, const ParamValues& params, const Camera& camera,
                 const glm::mat4& projection, glm::ivec4 target, glm::ivec4 tile);

 private:
  using FrameUniforms = glintlab::FrameUniforms;  // std140, src/core/gpu_contract.hpp
  /// Draws every shape with `module` (a method's or the reference's) in the forward pass, each
  /// with the program variant for its material, then the visible emitters.
  void draw_scene(const std::string& module, const ParamValues& params, const FrameUniforms& frame);
  /// Makes what `method` reads with `params` resident (its tables and resources), to be bound by
  /// the draws that follow.
  void prepare(const MethodDescriptor& method, const ParamValues& params);
  /// The forward program for `module`, specialised on the scene's lights and the material;
  /// looked up once per (module, variant), not per draw.
  GLuint forward_program(const std::string& module, int material);
  RenderTarget& target(int width, int height);

  ShaderLibrary& shaders_;
  const GpuScene& scene_;
  gl::Buffer frame_ubo_;
  gl::VertexArray empty_vertex_array_;  ///< the background pass's triangle has no vertex attributes
  std::unique_ptr<RenderTarget> target_;
  std::map<std::pair<std::string, MaterialVariant>, GLuint> forward_programs_;
  std::vector<std::string> method_resources_;  ///< what the method of the last prepare() reads
  ParamValues method_params_;                  ///< and its parameters (the resources' context)
};

}  // namespace glintlab
