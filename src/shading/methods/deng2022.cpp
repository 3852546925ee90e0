// Descriptor of `deng2022`: the footprint's NDF from a CP-compressed pyramid of NDF images (Deng et al. 2022).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

namespace {
/// A setting of the precompute (src/prefilter/prefiltered_ndf.hpp, PrefilterSettings): read by the
/// renderer to choose the pyramid it binds, never by the module.
ParamDecl precompute_param(std::string name, float value, float min, float max, std::string description) {
  ParamDecl p{std::move(name), value, min, max, std::move(description)};
  p.host_only = true;
  return p;
}
}  // namespace

MethodDescriptor deng2022_method() {
  return {
      .id = "deng2022",
      .title = "Deng et al. 2022 (tensor-compressed NDF prefiltering, real time)",
      .citation = "H. Deng, Y. Liu, B. Wang, J. Yang, L. Ma, N. Holzschuch, L.-Q. Yan, Constant-Cost Spatio-Angular "
                  "Prefiltering of Glinty Appearance Using Tensor Decomposition, ACM TOG 41(2), 2022",
      .summary = "On normal-map-glints materials, the NDF of the pixel's footprint comes from a precomputed pyramid "
                 "of NDF images (Yan 2016's P-NDF of Gaussian footprints on a grid per level, sigma doubling per "
                 "level) cut into angular blocks, each group of blocks CP-decomposed, queried with the isotropic "
                 "footprint of the pixel's footprint's area (finer than the first level: yan2016's element sum); a "
                 "point query for delta lights and a box query through the factors' prefix sums for lights with "
                 "extent, trilinear across footprint centres and levels: a cost independent of the footprint and of "
                 "the light. The "
                 "pyramid is precomputed on first use per map and settings and cached. Other materials are "
                 "shaded as by conventional (lights with extent by LTC).",
      .params = {footprint_sigma_param(),
                 {"small_footprints", 0, 0, 1,
                  "footprints finer than the pyramid's first level: yan2016 (summed over the map's elements, as "
                  "the paper does; bounded by that level's size) or clamp (the first level's NDF: blurred)",
                  {"yan2016", "clamp"}},
                 precompute_param("rank", 16.0f, 1.0f, 64.0f,
                                  "CP rank of every group's tensor (the paper: 16, 32 for flakes)"),
                 precompute_param("ndf_resolution", 64.0f, 16.0f, 256.0f,
                                  "N: the NDF images are N x N over the map's normals"),
                 precompute_param("block_size", 16.0f, 4.0f, 64.0f,
                                  "B: angular blocks of B x B pixels, a divisor of ndf_resolution with at most 8 blocks a side"),
                 precompute_param("base_footprints", 128.0f, 16.0f, 1024.0f,
                                  "footprints per side of the finest level (at most the map's size): its sigma and stride are "
                                  "map size / this texels, so storage does not grow with the map"),
                 precompute_param("group_footprints", 4.0f, 1.0f, 16.0f,
                                  "footprints per side of a group: the blocks of group_footprints^2 neighbouring footprints "
                                  "share one tensor"),
                 precompute_param("elements_per_texel", 2.0f, 1.0f, 2.0f,
                                  "Yan 2016's elements per texel and axis behind the NDF images")},
      .tables = {"ltc-ggx"},  // other materials' lights with extent, as conventional
      .reads_prefiltered_ndfs = true,
  };
}

GLINTLAB_REGISTER_METHOD(deng2022_method, 850);

}  // namespace glintlab
