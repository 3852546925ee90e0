// Descriptor of `yan2016`: the P-NDF of the pixel's footprint (Yan et al. 2016) by brute force over its elements.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor yan2016_method() {
  return {
      .id = "yan2016",
      .title = "Yan et al. 2016 (position-normal distributions, brute force)",
      .citation = "L.-Q. Yan, M. Hasan, S. Marschner, R. Ramamoorthi, Position-Normal Distributions for Efficient "
                  "Rendering of Specular Microstructure, SIGGRAPH 2016 (TOG 35(4))",
      .summary = "On normal-map-glints materials, the NDF of the pixel's Gaussian footprint (footprint_sigma pixels "
                 "mapped to the normal map's texels by the uv Jacobian) is the position-normal distribution of the "
                 "map's Gaussian elements with linearised normals and the intrinsic roughness sigma_r, summed by "
                 "brute force over every element within 3 sigma of the footprint: a cost that grows with the "
                 "footprint (the baseline deng2022 beats), and the element model's own error (not the surface's "
                 "exact NDF). Past max_elements the sum runs over a stratified subset, one element per s x s cell "
                 "chosen by a hash fixed on the surface: unbiased, never a truncated footprint. Delta lights take "
                 "P at the half vector; lights with extent its mean over the light's half-vector region as an "
                 "axis-aligned box. Other materials are shaded as by conventional (lights with extent by LTC).",
      .params = {footprint_sigma_param(),
                 {"max_elements", 16384.0f, 256.0f, 60000.0f,
                  "elements summed per pixel, the scene's lights together (at most 60000: llvmpipe stops a "
                  "shader's loops after 65535 iterations); a footprint whose 3-sigma box holds more is summed "
                  "over a stratified subset of that many, so the cost is O(min(box, max_elements))",
                  {},
                  false,
                  {},
                  false,
                  /*integer=*/true},
                 {"elements_per_texel", 0, 0, 1,
                  "k: the map as k x k Gaussian elements per texel (Yan et al. use 1 to 4); 2 follows the bilinear "
                  "field more closely at 4x the cost",
                  {"1", "2"},
                  /*compile_time=*/true},
                 environment_lobes_param(), environment_lobe_cones_param()},
      .tables = {"ltc-ggx"},  // other materials' lights with extent, as conventional
      // The normal-map-glints materials' elements (k per texel) and the environment's lobes.
      .resources = {"position-normal-elements", "environment-lobes"},
      .material_kinds = {"normal-map-glints"},
      .path_footprint_ndf = true,
  };
}

GLINTLAB_REGISTER_METHOD(yan2016_method, 840);

}  // namespace glintlab
