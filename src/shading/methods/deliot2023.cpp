// Descriptor of `deliot2023`: glinty appearance by distributed binomial laws on anisotropic
// grids (Deliot & Belcour 2023), with the fixes its public code needed.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor deliot2023_method() {
  return {
      .id = "deliot2023",
      .title = "Deliot & Belcour 2023 (binomial laws on anisotropic grids)",
      .citation = "T. Deliot, L. Belcour, Real-Time Rendering of Glinty Appearance using Distributed Binomial Laws "
                  "on Anisotropic Grids, HPG 2023 (CGF 42(8))",
      .summary = "A binomial-glints material's discrete microfacets, counted: the pixel's uv footprint ellipse "
                 "picks four anisotropic grids (level of detail, anisotropy and angle, interpolated "
                 "tetrahedrally); in each, a triangle grid of surface cells with random density and slope-grid "
                 "offset per vertex; per vertex and cell of a slope grid over the projected half vector, the "
                 "facets that reflect, binomial with p = R D(h) / D(0), drawn as a gate and an approximation of "
                 "the remaining count. The expected NDF is the material's GGX. Lights with extent are points at "
                 "their centre (the paper's ad-hoc R stands for their size). Procedural random numbers: no "
                 "table. Other materials are shaded as by conventional (lights with extent by LTC).",
      .params = {binomial_screen_space_scale_param(), binomial_remaining_count_param()},
      // Other materials' lights with extent: conventional's default (area_lights = ltc).
      .tables = {"ltc-ggx"},
      .material_kinds = {"binomial-glints"},
  };
}

GLINTLAB_REGISTER_METHOD(deliot2023_method, 820);

}  // namespace glintlab
