#pragma once
// The `raster` reference backend: the forward renderer with passes/reference.glsl in the method
// slot, at k x k sub-pixels per pixel in tiles, filtered down to the film by the pass's pixel
// filter (render/subpixel_filter.hpp). Each sub-pixel
// evaluates the surface itself (normal maps at their base level) and integrates every light with
// extent by multiple importance sampling (docs/methods.md, "Ground truth").
#include <string>

#include "render/reference_backend.hpp"
#include "render/renderer.hpp"

namespace glintlab {

class RasterReference final : public ReferenceBackend {
 public:
  /// `id` and the reference module it runs in the method slot (kReferenceModule, or one of its
  /// variants, e.g. kRealisationReferenceModule).
  RasterReference(const ReferenceBackendContext& context, std::string id = "raster",
                  std::string module = kReferenceModule);

  [[nodiscard]] std::string id() const override { return id_; }
  /// Hash of the full GLSL text of every program this backend runs on the scene (each material's
  /// variant, the emitters, both pixel filters): editing a method's module leaves it unchanged.
  [[nodiscard]] std::uint64_t estimator_hash() const override;
  Frame render_pass(const Camera& camera, int width, int height, const ReferencePass& pass,
                    const ProgressFn& progress = {}) override;

 private:
  ShaderLibrary& shaders_;
  const GpuScene& scene_;
  Renderer& renderer_;
  std::string id_;
  std::string module_;
  mutable std::uint64_t estimator_hash_ = 0;  ///< computed once: the programs' text is fixed per scene
};

}  // namespace glintlab
