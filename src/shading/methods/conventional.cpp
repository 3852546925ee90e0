// Descriptor of `conventional`: shading evaluated once at the pixel centre (the baseline).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor conventional_method() {
  return {
      .id = "conventional",
      .title = "Conventional (pixel-centre shading)",
      .citation = "baseline: Cook-Torrance microfacet BRDF (GGX or Beckmann, height-correlated Smith, "
                  "Schlick Fresnel) plus Lambert; lights with extent by linearly transformed cosines (Heitz et al. "
                  "2016) or the lobe's mass over the light",
      .summary = "Evaluates the BRDF once at the pixel centre with the interpolated (normal-mapped) normal. "
                 "Lights with extent (area_lights): by default the GGX lobe's linearly transformed cosine "
                 "integrated over the light's polygon or disk, horizon clipped, and the exact Lambert term; or "
                 "the lobe's mass over the light's image in slope space (closed form), with Fresnel and masking "
                 "at the representative point (Karis 2013), which a mirror sees as the light's radiance where "
                 "the reflected ray hits it, continuously in alpha.",
      .params = {area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(conventional_method, 100);

}  // namespace glintlab
