// Descriptor of `kaplanyan-beckmann` (Kaplanyan, Hill, Patney, Lefohn 2016).
#include "core/pixel_filter_width.hpp"
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kaplanyan_beckmann_method() {
  return {
      .id = "kaplanyan-beckmann",
      .title = "Kaplanyan et al. (Beckmann, full covariance)",
      .citation = kKaplanyan2016Citation,
      .summary =
          "Convolves the NDF with the pixel footprint in slope space: the derivatives U = [dh/dx dh/dy] of the "
          "slope-space half vector (towards the light's centre) give, for a Gaussian pixel filter of standard "
          "deviation sigma = " +
          pixel_filter_sigma_text() +
          " px (the talk's; glintlab's one pixel-filter width, PIXEL_FILTER_SIGMA), the covariance C = sigma^2 U U^T, "
          "and the lobe's roughness matrix becomes R' = R + 2C, non-axis-aligned. Exact for Beckmann; GGX materials "
          "use the same matrix as a proxy.",
      .params = {fp_max_param(),
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(kaplanyan_beckmann_method, 400);

}  // namespace glintlab
