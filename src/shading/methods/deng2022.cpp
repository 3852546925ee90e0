// Descriptor of `deng2022`: the footprint's NDF from a CP-compressed pyramid of NDF images (Deng et al. 2022).
#include "prefilter/prefilter_params.hpp"
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor deng2022_method() {
  MethodDescriptor method{
      .id = "deng2022",
      .title = "Deng et al. 2022 (tensor-compressed NDF prefiltering, real time)",
      .citation = "H. Deng, Y. Liu, B. Wang, J. Yang, L. Ma, N. Holzschuch, L.-Q. Yan, Constant-Cost Spatio-Angular "
                  "Prefiltering of Glinty Appearance Using Tensor Decomposition, ACM TOG 41(2), 2022",
      .summary = "On normal-map-glints materials, the NDF of the pixel's footprint comes from a precomputed pyramid "
                 "of NDF images (Yan 2016's P-NDF of Gaussian footprints on a grid per level, sigma doubling per "
                 "level) cut into angular blocks, each group of blocks CP-decomposed, queried with isotropic "
                 "footprints along the pixel's footprint's major axis (finer than the first level: yan2016's element "
                 "sum); a "
                 "point query for delta lights and a box query through the factors' prefix sums for lights with "
                 "extent, trilinear across footprint centres and levels: a cost independent of the footprint and of "
                 "the light. The "
                 "pyramid is precomputed on first use per map and settings and cached. Other materials are "
                 "shaded as by conventional (lights with extent by LTC).",
      .params = {footprint_sigma_param(),
                 {"small_footprints", 0, 0, 2,
                  "footprints whose minor axis is finer than the pyramid's first level: yan2016 (summed over the "
                  "map's elements, 2 per texel and axis as the pyramid's images, as the paper does; bounded by that "
                  "level's size), yan2016-k1 (1 element per texel: 4x cheaper, far coarser up close) or clamp (the "
                  "first level's NDF: blurred)",
                  {"yan2016", "yan2016-k1", "clamp"},
                  /*compile_time=*/true},
                 {"box_queries", 0, 0, 1,
                  "box queries (lights with extent): prefix-tables (per footprint, 2D prefix sums over its angular "
                  "blocks: any box is its 4 corners, a constant cost; 2R + 1 more floats per block of every "
                  "footprint) or blocks (the paper's eq. 7 block by block: no more storage, a cost growing with the "
                  "blocks the box overlaps, up to (N/B)^2)",
                  {"prefix-tables", "blocks"},
                  /*compile_time=*/true},
                 {"anisotropic_probes", 8.0f, 1.0f, 16.0f,
                  "isotropic pyramid queries along an anisotropic footprint's major axis, at most (1: one query of "
                  "the footprint's area, blurred along the minor axis and cut along the major one)",
                  {}, false, {}, false, true},
                 environment_lobes_param(), environment_lobe_cones_param()},
      .tables = {"ltc-ggx"},  // other materials' lights with extent, as conventional
      // The normal-map-glints materials' pyramids of its precompute settings, and their elements
      // for the fallback (none with small_footprints = clamp).
      .resources = {"prefiltered-ndf", "position-normal-elements", "environment-lobes"},
      .material_kinds = {"normal-map-glints"},
      .path_footprint_ndf = true,
  };
  // The precompute's settings, declared with PrefilterSettings (src/prefilter/prefilter_params.hpp).
  for (ParamDecl& p : prefilter_params()) method.params.push_back(std::move(p));
  return method;
}

GLINTLAB_REGISTER_METHOD(deng2022_method, 850);

}  // namespace glintlab
