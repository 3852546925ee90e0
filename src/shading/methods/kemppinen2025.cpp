// Descriptor of `kemppinen2025`: glinty NDFs evaluated and sampled in constant time (Kemppinen et
// al. 2025), re-derived from the paper's description.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kemppinen2025_method() {
  return {
      .id = "kemppinen2025",
      .title = "Kemppinen et al. 2025 (glinty NDFs in constant time)",
      .citation = "P. Kemppinen, L. Paulin, T. Thonat, J. Thiery, J. Lehtinen, T. Boubekeur, Evaluating and Sampling "
                  "Glinty NDFs in Constant Time, SIGGRAPH Asia 2025 (ACM TOG 44(6))",
      .summary = "A point-process-glints material's facets, points of a 4D process (a position in uv, a normal) on "
                 "an implicit multiscale grid: the pixel's Gaussian footprint picks the level whose spatial cells "
                 "are 8 of its deviations wide, and the NDF sums the lobes of the facets in the 2 x 2 spatial by 2 x "
                 "2 angular cells nearest the point and the half vector, at two levels blended by facets surviving "
                 "one by one, plus the expectation of every facet not visited (the mean is the material's GGX or "
                 "Beckmann NDF exactly). 32 facets a light, nothing stored. Lights with extent are points at their "
                 "centre. Other materials are shaded as by conventional (lights with extent by LTC).",
      .params = {{"footprint_scale", 1.0f, 0.25f, 4.0f,
                  "the spatial footprint's deviation in units of the pixel filter's (larger: smoother glints, "
                  "like the paper's pixel_filter_size)"}},
      // Other materials' lights with extent: conventional's default (area_lights = ltc).
      .tables = {"ltc-ggx"},
      .material_kinds = {"point-process-glints"},
  };
}

GLINTLAB_REGISTER_METHOD(kemppinen2025_method, 860);

}  // namespace glintlab
