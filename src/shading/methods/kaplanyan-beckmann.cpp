// Descriptor of `kaplanyan-beckmann` (Kaplanyan, Hill, Patney, Lefohn 2016).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kaplanyan_beckmann_method() {
  return {
      .id = "kaplanyan-beckmann",
      .title = "Kaplanyan et al. (Beckmann, full covariance)",
      .citation = kKaplanyan2016Citation,
      .summary = "Convolves the NDF with the pixel footprint in slope space: the derivatives U = [dh/dx dh/dy] of the slope-space half vector (towards the light's centre) give, for the talk's Gaussian pixel filter of standard deviation 0.5 px, the covariance C = U U^T / 4, and the lobe's roughness matrix becomes R' = R + 2C, non-axis-aligned. Exact for Beckmann; GGX materials use the same matrix as a proxy.",
      .params = {fp_max_param(),
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(kaplanyan_beckmann_method, 400);

}  // namespace glintlab
