// Material kind `glinty`: the procedural, discrete Beckmann microsurface of Chermain et al. 2020
// and 2021, whose limit at large footprints is the Beckmann NDF of slope deviations sigma and
// correlation rho; shaders/materials/glinty.glsl.
#include <cmath>

#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {
constexpr float kDefaultSigma = 0.1f;
constexpr double kMinSigma = 0.005, kMaxSigma = 0.7;
constexpr double kMaxRho = 0.99;
}  // namespace

MaterialKind glinty_material_kind() {
  return {
      .id = "glinty",
      .title = "Glinty (Chermain et al.'s procedural discrete microfacets)",
      .citation = "X. Chermain, B. Sauvage, J.-M. Dischler, C. Dachsbacher, Procedural Physically based BRDF for "
                  "Real-Time Rendering of Glints, Pacific Graphics 2020; X. Chermain, S. Lucas, B. Sauvage, "
                  "J.-M. Dischler, C. Dachsbacher, Real-Time Geometric Glint Anti-Aliasing with Normal Map Filtering, "
                  "I3D 2021",
      .summary = "A Beckmann microsurface given by its slope deviations `sigma` (alpha = sqrt(2) sigma) and "
                 "correlation `rho`, made of discrete microfacets: a patch-SDF of multiscale slope marginals (the "
                 "glint dictionary) over a grid of cells, e^log_density facets per unit of uv area. Methods that do "
                 "not know the kind shade its smooth limit, the Beckmann lobe of sigma and rho.",
      .params = {{"log_density", 20.0f, 0.0, 60.0,
                  "natural log of the number of microfacets per unit of **uv** area (the mesh's uv, before "
                  "`normal_map_tiling`)"},
                 {"relative_area", 1.0f, 0.0, 1.0,
                  "fraction of the surface's cells that hold microfacets (sparser glitter below 1)"},
                 {"max_anisotropy", 4.0f, 1.0, 64.0,
                  "clamp of the pixel footprint's eccentricity: it bounds the cells per pixel and level to about "
                  "pi sqrt(5 (1 + 4 A^2)), so that above about 7 the guard of 100 cells per level can truncate a "
                  "footprint (2020's default was 8, 2021's is 4)"}},
      .lobe_keys = {{"sigma", "number or [sx, sy]", number_text(kDefaultSigma), range_text(kMinSigma, kMaxSigma),
                     "slope standard deviations along +u and +v (alpha = sqrt(2) sigma)"},
                    {"rho", "number", "0", range_text(-kMaxRho, kMaxRho), "slope correlation (ignored by `chermain2020`)"}},
      .parse_lobe =
          [](TomlReader& r, Material& m) {
            for (const char* key : {"alpha", "ndf"})
              if (r.has(key))
                r.fail(key, "is not a key of a glinty material; it has sigma (alpha = sqrt(2) sigma) and a Beckmann NDF");
            m.ndf = Ndf::Beckmann;
            m.alpha = std::sqrt(2.0f) * r.get_vec2("sigma", glm::vec2(kDefaultSigma), kMinSigma, kMaxSigma);
            m.rho = static_cast<float>(r.get_number("rho", 0.0, -kMaxRho, kMaxRho));
          },
      .resources = {"table:glint-dictionary"},
  };
}

GLINTLAB_REGISTER_MATERIAL_KIND(glinty_material_kind, 100);

}  // namespace glintlab
