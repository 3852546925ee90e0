// Descriptor of `kaplanyan-ggx` (Kaplanyan, Hill, Patney, Lefohn 2016).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kaplanyan_ggx_method() {
  return {
      .id = "kaplanyan-ggx",
      .title = "Kaplanyan et al. (GGX rectangle integral)",
      .citation = kKaplanyan2016Citation,
      .summary = "Averages the NDF over the footprint's bounding rectangle in slope space, in closed form (eight arctangents for GGX, four erf for Beckmann), then maps back to half-vector space by the 1 / cos^4 Jacobian. The rectangle is clamped above by fp_max; narrow sides and boxes in the tails are integrated by Gauss-Legendre quadrature.",
      .params = {fp_max_param(),
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(kaplanyan_ggx_method, 420);

}  // namespace glintlab
