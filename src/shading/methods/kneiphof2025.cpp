// Descriptor of `kneiphof2025`: glints under image-based lighting (Kneiphof & Klein 2025) on the
// binomial counting of deliot2023 and kneiphof2024.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kneiphof2025_method() {
  return {
      .id = "kneiphof2025",
      .title = "Kneiphof & Klein 2025 (glints under image-based lighting)",
      .citation = "T. Kneiphof, R. Klein, Real-time Image-based Lighting of Glints, EGSR 2025 (CGF 44(4), "
                  "arXiv 2507.02674)",
      .summary = "A binomial-glints material under an environment: the environment cut into four regions of "
                 "luminance (black and three log-spaced levels) whose weight maps are prefiltered by the "
                 "radiance's own GGX chain; the footprint's facets that reflect into the hemisphere (the D-only "
                 "LTC's magnitude over the NDF's total) counted as by deliot2023 and split among the regions by "
                 "hierarchical binomial draws with the prefiltered weights at the reflected direction; the "
                 "regions' luminance found over expected scales the split-sum radiance (its mean is the split "
                 "sum's). Compact lights as kneiphof2024 (undivided, delta lights with the material's R). Other "
                 "materials are shaded as by conventional.",
      .params = {binomial_screen_space_scale_param(), binomial_remaining_count_param()},
      // The D-only LTC for p, the GGX LTC for the smooth integrals (also other materials' lights).
      .tables = {"ltc-ggx", "ltc-ndf"},
      .resources = {"environment-glint-weights"},
      .material_kinds = {"binomial-glints"},
  };
}

GLINTLAB_REGISTER_METHOD(kneiphof2025_method, 835);

}  // namespace glintlab
