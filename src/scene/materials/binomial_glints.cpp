// Material kind `binomial-glints`: discrete microfacets counted by binomial laws whose expectation
// is the smooth GGX NDF of the material's alpha (Deliot & Belcour 2023); shaders/materials/binomial-glints.glsl.
#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

MaterialKind binomial_glints_material_kind() {
  return {
      .id = "binomial-glints",
      .title = "Binomial glints (Deliot & Belcour's discrete microfacets on anisotropic grids)",
      .citation = "A. Deliot, L. Belcour, Real-Time Rendering of Glinty Appearance using Distributed Binomial Laws on "
                  "Anisotropic Grids, EGSR 2023 (CGF 42(4))",
      .summary = "Discrete microfacets counted, per surface cell and slope cell, by a binomial law whose expectation "
                 "is the smooth GGX NDF of roughness `alpha`: e^log_density facets per unit of uv area, each "
                 "reflecting with probability p = R D(h) / D(0). Methods that do not know the kind shade its smooth "
                 "limit, the GGX lobe of alpha.",
      .params = {{"log_density", 20.0f, 0.0, 50.0, "ln of the number of microfacets per unit of uv area"},
                 {"microfacet_roughness", 0.02f, 1e-4, 1.0,
                  "the paper's R: p = R D(h) / D(0), a facet's share of the lobe"},
                 {"density_randomization", 0.0f, 0.0, 10.0, "standard deviation of ln density between surface cells"},
                 {"slope_grid_scale", 16.0f, 0.1, 1000.0, "slope cells per unit of the projected half vector h.xy"}},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            if (r.has("ndf"))
              r.fail("ndf", "is not a key of a binomial-glints material; its NDF is GGX (of roughness alpha)");
            m.ndf = Ndf::GGX;
            m.alpha = r.get_vec2("alpha", glm::vec2(0.2f), 0.01, 1.0);
          },
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(binomial_glints_material_kind, 200);

}  // namespace glintlab
