// Material kind `microfacet`: the Cook-Torrance microfacet BRDF (GGX or Beckmann NDF,
// height-correlated Smith masking-shadowing, Schlick Fresnel) plus Lambert; shaders/materials/microfacet.glsl.
#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {
constexpr float kMicrofacetDefaultAlpha = 0.1f;
constexpr double kMicrofacetMinAlpha = 0.0, kMicrofacetMaxAlpha = 1.0;
}  // namespace

MaterialKind microfacet_material_kind() {
  return {
      .id = "microfacet",
      .title = "Microfacet (Cook-Torrance) and Lambert",
      .citation = "B. Walter, S. R. Marschner, H. Li, K. E. Torrance, Microfacet Models for Refraction through Rough "
                  "Surfaces, EGSR 2007; E. Heitz, Understanding the Masking-Shadowing Function in Microfacet-Based "
                  "BRDFs, JCGT 3(2), 2014",
      .summary = "A smooth microfacet lobe of roughness alpha (anisotropic: [alpha_x, alpha_y]) with the NDF `ndf`, "
                 "plus a Lambert term. What every method is built for; every other kind's smooth limit is one.",
      .params = {},
      .lobe_keys = {{"ndf", "string", "\"ggx\"", "ggx, beckmann", "microfacet distribution"},
                    {"alpha", "number or [ax, ay]", number_text(kMicrofacetDefaultAlpha), range_text(kMicrofacetMinAlpha, kMicrofacetMaxAlpha),
                     "roughness alpha (anisotropic: along +u and +v, or the anisotropy direction of glTF materials)"}},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            m.ndf = r.get_string("ndf", "ggx", {"ggx", "beckmann"}) == "ggx" ? Ndf::GGX : Ndf::Beckmann;
            m.alpha = r.get_vec2("alpha", glm::vec2(kMicrofacetDefaultAlpha), kMicrofacetMinAlpha, kMicrofacetMaxAlpha);
          },
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(microfacet_material_kind, 0);

}  // namespace glintlab
