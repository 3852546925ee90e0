// Material kind `normal-map-glints`: Yan et al. 2016's microsurface, the normal map itself, each
// point's projected normal s = h.xy Gaussian about the map's bilinear normal with deviation
// intrinsic_roughness per axis (docs/scene-format.md); shaders/materials/normal-map-glints.glsl.
#include <cmath>

#include "scene/materials/material.hpp"
#include "scene/materials/normal_glints.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

MaterialKind normal_map_glints_material_kind() {
  return {
      .id = "normal-map-glints",
      .title = "Normal-map glints (Yan et al.'s microsurface: the normal map itself)",
      .citation = "L.-Q. Yan, M. Hasan, S. Marschner, R. Ramamoorthi, Position-Normal Distributions for Efficient "
                  "Rendering of Specular Microstructure, SIGGRAPH 2016",
      .summary = "The normal map is the microsurface: at a point u the projected normal s = h.xy is Gaussian about "
                 "the map's bilinear normal n(u).xy with deviation `intrinsic_roughness` per axis, D(h) = P(h.xy); "
                 "Smith masking of the whole microsurface's Beckmann alpha. Requires `normal_map`. Methods that do "
                 "not know the kind shade its smooth limit, the Beckmann lobe of alpha = sqrt(2) intrinsic_roughness "
                 "over the normal map.",
      .params = {{"intrinsic_roughness", 0.01f, 0.001, 0.3,
                  "sigma_r: standard deviation of the projected normal h.xy about the map's normal n(u).xy, per axis "
                  "(a flat map is Beckmann of alpha = sqrt(2) sigma_r)"},
                 {"masking_alpha", 0.01f, 0.0, 1e6,
                  "Beckmann alpha of the whole microsurface, sqrt(E[|b|^2] + 2 sigma_r^2) with b = n.xy / n.z over "
                  "the map's texels: Smith masking-shadowing only (derived from the map)",
                  /*derived=*/true},
                 {"wang_tiles", 0.0f, 0.0, 4096.0,
                  "tiles along a side of the surface of a Wang-tiled normal map (its `wang_tiles.tiles`; 0: a plain "
                  "map); the tile size is the stored atlas's side / 4",
                  /*derived=*/true},
                 {"wang_seed", 0.0f, 0.0, 16777215.0, "the Wang tiles' lattice hash seed (`wang_tiles.seed`)",
                  /*derived=*/true}},
      .lobe_keys = {},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            for (const char* key : {"alpha", "ndf", "sigma"})
              if (r.has(key))
                r.fail(key, "is not a key of a normal-map-glints material; its roughness is intrinsic_roughness "
                            "(Beckmann, alpha = sqrt(2) intrinsic_roughness) about the normal map's normals");
            m.ndf = Ndf::Beckmann;
            m.alpha = glm::vec2(std::sqrt(2.0f) * m.kind_param("intrinsic_roughness"));
          },
      .finish =
          [](TomlReader&, Material& m) {
            m.set_kind_param("masking_alpha",
                             normal_glint_masking_alpha(*m.normal_map, m.kind_param("intrinsic_roughness")));
            if (const auto& wang = m.normal_map->wang) {
              m.set_kind_param("wang_tiles", static_cast<float>(wang->tiles));
              m.set_kind_param("wang_seed", static_cast<float>(wang->seed));
            }
          },
      .requires_normal_map = true,
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(normal_map_glints_material_kind, 300);

}  // namespace glintlab
