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
                 "map's Gaussian elements with linearised normals and the intrinsic roughness sigma_r, summed over "
                 "every element within 3 sigma of the footprint: exact, and a cost that grows with the footprint "
                 "(the baseline deng2022 beats). Delta lights take P at the half vector; lights with extent its "
                 "mean over the light's half-vector region as an axis-aligned box. The truncation box is at most "
                 "max_radius texels (larger footprints are shrunk to fit). Other materials are shaded as by "
                 "conventional (lights with extent by LTC).",
      .params = {footprint_sigma_param(),
                 {"max_radius", 32.0f, 1.0f, 128.0f,
                  "largest half extent of the element search box in texels: a footprint whose 3-sigma box is "
                  "larger is shrunk to fit (under-blurred); the cost is O(max_radius^2 k^2) per light, and the "
                  "scene's lights together stay within llvmpipe's 65535 loop iterations"},
                 {"elements_per_texel", 0, 0, 1,
                  "k: the map as k x k Gaussian elements per texel (Yan et al. use 1 to 4); 2 follows the bilinear "
                  "field more closely at 4x the cost",
                  {"1", "2"},
                  /*compile_time=*/true}},
      .tables = {"ltc-ggx"},  // other materials' lights with extent, as conventional
      .material_kinds = {"normal-map-glints"},
  };
}

GLINTLAB_REGISTER_METHOD(yan2016_method, 840);

}  // namespace glintlab
