// Descriptor of `kaplanyan-rect` (Kaplanyan, Hill, Patney, Lefohn 2016).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kaplanyan_rect_method() {
  return {
      .id = "kaplanyan-rect",
      .title = "Kaplanyan et al. (axis-aligned rectangle)",
      .citation = kKaplanyan2016Citation,
      .summary = "Like kaplanyan-beckmann, but with the footprint's axis-aligned bounding rectangle, half sides fp = min((abs(dh/dx) + abs(dh/dy)) / 2, fp_max): R' = R + 2 diag(fp^2). Over-filters, for temporal stability: along each slope axis at least kaplanyan-beckmann's variance.",
      .params = {fp_max_param(),
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(kaplanyan_rect_method, 410);

}  // namespace glintlab
