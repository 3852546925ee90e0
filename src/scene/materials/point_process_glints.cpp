// Material kind `point-process-glints`: facets as a 4D point process on an implicit multiscale grid
// (Kemppinen et al. 2025), converging to the GGX or Beckmann NDF of the material's alpha as the
// footprint grows; shaders/materials/point-process-glints.glsl, shaders/glints/point-process/.
#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {
constexpr float kPointProcessDefaultAlpha = 0.2f;
constexpr double kPointProcessMinAlpha = 0.02, kPointProcessMaxAlpha = 1.0;
}  // namespace

MaterialKind point_process_glints_material_kind() {
  return {
      .id = "point-process-glints",
      .title = "Point-process glints (Kemppinen et al.'s facets on an implicit multiscale grid)",
      .citation = "P. Kemppinen, L. Paulin, T. Thonat, J. Thiery, J. Lehtinen, T. Boubekeur, Evaluating and Sampling "
                  "Glinty NDFs in Constant Time, SIGGRAPH Asia 2025 (ACM TOG 44(6))",
      .summary = "Facets with a position in uv and a normal, drawn on an implicit multiscale grid (nothing stored): "
                 "a footprint sums the lobes of the facets nearest its point and half vector, and takes the rest as "
                 "its expectation, so the mean NDF is the GGX or Beckmann NDF of `alpha` at every footprint. Methods "
                 "that do not know the kind shade its smooth limit, that lobe.",
      .params = {{"log_density", 16.0f, 0.0, 40.0,
                  "natural log of the facets per unit of **uv** area (before `normal_map_tiling`) and unit of the "
                  "angular square; pi/4 of them have a normal (those inside the square's disk)"},
                 {"microfacet_roughness", 0.01f, 1e-3, 0.2,
                  "the width of a facet's lobe in the angular square (the paper's sigma_g; 0.001 .. 0.1 in its "
                  "shader): smaller, sharper and brighter glints"}},
      .lobe_keys = {{"ndf", "string", "\"ggx\"", "ggx, beckmann", "the NDF the glints average to"},
                    {"alpha", "number or [ax, ay]", number_text(kPointProcessDefaultAlpha),
                     range_text(kPointProcessMinAlpha, kPointProcessMaxAlpha), "roughness of that NDF"}},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            if (r.has("sigma") || r.has("rho"))
              r.fail(r.has("sigma") ? "sigma" : "rho",
                     "is not a key of a point-process-glints material; it has ndf and alpha");
            m.ndf = r.get_string("ndf", "ggx", {"ggx", "beckmann"}) == "ggx" ? Ndf::GGX : Ndf::Beckmann;
            m.alpha = r.get_vec2("alpha", glm::vec2(kPointProcessDefaultAlpha), kPointProcessMinAlpha,
                                 kPointProcessMaxAlpha);
          },
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(point_process_glints_material_kind, 400);

}  // namespace glintlab
