#pragma once
// The `path` reference backend: a path tracer in wavefront form. Embree traces on the CPU (the rays
// of each sub-pixel sample, src/path/ray_scene.hpp); the hits are shaded on the GL device by the
// same GLSL as the raster reference (passes/path_direct.comp: the forward pass's surface record and
// the reference's estimator, sample by sample), which writes each light sample as a shadow ray;
// Embree answers them and the host adds what each light gives where it is visible. Direct light
// (max_depth = 1), with shadows: where nothing stands between a surface and its lights it draws
// what the raster reference draws, sample for sample (docs/methods.md, "The path tracer"). The
// backends `path:<method>` render a method's footprint NDF instead of the surface (docs/methods.md,
// "Methods in the path tracer").
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "path/ray_scene.hpp"
#include "render/reference_backend.hpp"
#include "render/renderer.hpp"
#include "core/pixel_filter_width.hpp"
#include "shading/method_list.hpp"

namespace glintlab {

struct PassTile;

class PathReference final : public ReferenceBackend {
 public:
  /// `shadows` false: every shadow ray is taken as unblocked (`path-unshadowed`, direct light
  /// only): the raster reference's light transport, traced, to hold the two backends to each other
  /// on any scene.
  explicit PathReference(const ReferenceBackendContext& context, bool shadows = true);
  /// `path:<method>`: normal-map-glints materials as `method`'s footprint NDF (its module compiled
  /// with METHOD_AS_FOOTPRINT_NDF in their $MATERIAL slot: shaders/materials/normal-map-glints-footprint.glsl),
  /// evaluated and sampled, with an environment by the method's lobes where it fits any; every
  /// other material as `path` has it. The method's appearance rendered offline, not ground truth.
  PathReference(const ReferenceBackendContext& context, MethodChoice method);

  [[nodiscard]] std::string id() const override;
  /// Hash of the shading programs' full text on this scene, the filters' and the tracer's version.
  [[nodiscard]] std::uint64_t estimator_hash() const override;
  Frame render_pass(const Camera& camera, int width, int height, const ReferencePass& pass,
                    const ProgressFn& progress = {}) override;

 private:
  /// The shading program of a material's variant, and its defines.
  GLuint shading_program(int material);
  [[nodiscard]] ShaderDefines program_defines(int material) const;
  /// Whether `material` is shaded by the method's footprint NDF (path:<method>).
  [[nodiscard]] bool by_method(int material) const;
  /// The slots the shading pass writes shadow rays into, per hit.
  [[nodiscard]] std::size_t shadow_rays_per_hit(const ReferencePass& pass) const;
  /// Shades one tile's samples: their radiance in `total` and `specular` (GL's row order), path
  /// vertex by path vertex.
  void shade_tile(const Camera& camera, int width, int height, const ReferencePass& pass, const PassTile& tile,
                  std::vector<glm::vec4>& total, std::vector<glm::vec4>& specular);
  /// The background (a visible environment) that camera rays in `directions` see, in `total` at
  /// the samples `missed`.
  void shade_background(const std::vector<std::size_t>& missed, std::vector<glm::vec4> directions,
                        std::vector<glm::vec4>& total);

  /// A storage buffer kept from tile to tile and only grown: a tile's shadow rays take up to 96 MiB,
  /// and allocating (and clearing) them per tile cost more than shading them.
  struct DeviceBuffer {
    gl::Buffer buffer;
    std::size_t capacity = 0;
    /// The buffer, with room for at least `bytes`.
    GLuint hold(std::size_t bytes);
  };

  ShaderLibrary& shaders_;
  const GpuScene& scene_;
  RayScene rays_;
  bool shadows_;
  std::optional<MethodChoice> method_;  ///< path:<method>
  std::string method_module_;           ///< its generated module (method_program_module)
  std::vector<std::string> method_resources_;
  float footprint_sigma_ = kPixelFilterSigma;  ///< the method's: a footprint step's deviation (ray cones)
  DeviceBuffer hits_, shadow_rays_, emission_, bounces_;
  std::vector<glm::vec4> shadow_host_;  // the shadow rays read back, three vec4 each (grown, never shrunk)
  std::map<int, GLuint> programs_;  // by material
  mutable std::uint64_t estimator_hash_ = 0;
};

}  // namespace glintlab
