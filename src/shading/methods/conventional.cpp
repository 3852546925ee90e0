// Descriptor of `conventional`: shading evaluated once at the pixel centre (the baseline).
#include "shading/methods/shared_params.hpp"

namespace glintlab {

MethodDescriptor conventional_method() {
  return {
      .id = "conventional",
      .title = "Conventional (pixel-centre shading)",
      .citation = "baseline: Cook-Torrance microfacet BRDF (GGX or Beckmann, height-correlated Smith, "
                  "Schlick Fresnel) plus Lambert; representative-point area lights (Karis 2013)",
      .summary = "Evaluates the BRDF once at the pixel centre with the interpolated (normal-mapped) normal. "
                 "Mirror-like surfaces (max alpha below mirror_alpha) take the light's radiance where the "
                 "reflected ray hits an area light; rougher ones use the representative point with a "
                 "widened, energy-normalised lobe.",
      .params = {mirror_alpha_param()},
      .tables = {},
  };
}

}  // namespace glintlab
