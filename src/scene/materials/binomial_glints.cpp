// Material kind `binomial-glints`: discrete microfacets counted by binomial laws whose expectation
// is the smooth GGX NDF of the material's alpha (Deliot & Belcour 2023); shaders/materials/binomial-glints.glsl.
#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {
constexpr float kBinomialDefaultAlpha = 0.2f;
constexpr double kBinomialMinAlpha = 0.01, kBinomialMaxAlpha = 1.0;
}  // namespace

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
      .params = {{"log_density", 20.0f, 0.0, 50.0,
                  "natural log of the number of microfacets per unit of **uv** area (as for `glinty`, before "
                  "`normal_map_tiling`)"},
                 {"microfacet_roughness", 0.02f, 1e-4, 1.0,
                  "the paper's R: the share of the lobe one facet reflects from a delta light, p = R D(h) / D(0) "
                  "(0.012 .. 0.036 in Kneiphof & Klein's scenes; `deliot2023` also uses it for lights with extent, "
                  "`kneiphof2024` and the reference do not); smaller R: fewer, brighter glints"},
                 {"density_randomization", 0.0f, 0.0, 10.0,
                  "standard deviation of the natural log of the density between surface cells (patchier glitter; "
                  "the mean NDF is unchanged)"},
                 {"slope_grid_scale", 16.0f, 0.1, 1000.0,
                  "cells of the slope grid per unit of the projected half vector h.xy: how far the half vector turns "
                  "before a glint changes (Kneiphof & Klein's `HalfwaySlopeScale`; the paper used 1/R)"}},
      .lobe_keys = {{"alpha", "number or [ax, ay]", number_text(kBinomialDefaultAlpha), range_text(kBinomialMinAlpha, kBinomialMaxAlpha),
                     "GGX roughness of the smooth NDF the glints have as expectation"}},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            if (r.has("ndf"))
              r.fail("ndf", "is not a key of a binomial-glints material; its NDF is GGX (of roughness alpha)");
            m.ndf = Ndf::GGX;
            m.alpha = r.get_vec2("alpha", glm::vec2(kBinomialDefaultAlpha), kBinomialMinAlpha, kBinomialMaxAlpha);
          },
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(binomial_glints_material_kind, 200);

}  // namespace glintlab
