// Descriptor of `kneiphof2024`: glints under area lights (Kneiphof & Klein 2024) on the binomial
// counting of deliot2023.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor kneiphof2024_method() {
  return {
      .id = "kneiphof2024",
      .title = "Kneiphof & Klein 2024 (glints under area lights)",
      .citation = "T. Kneiphof, R. Klein, Real-Time Rendering of Glints in the Presence of Area Lights, "
                  "Pacific Graphics 2024 (arXiv 2408.13611)",
      .summary = "A binomial-glints material's facets counted as by deliot2023, but with the probability that a "
                 "facet reflects the light itself: the NDF's mass over the light's half-vector image over the "
                 "NDF's total, from a D-only LTC for large lights (or, the paper's cheap mode, the GGX LTC's "
                 "integral with the D-only magnitude) and from the NDF as constant over a small cap for lights "
                 "small in their largest extent (blended where their errors cross). The found over the expected "
                 "reflecting facets (the glint factor) scales the smooth GGX's LTC integral over the light. Quad lights "
                 "can be cut into 2 x 2 or 4 x 4 cells whose facets are split hierarchically. Delta lights: "
                 "the material's R, as deliot2023, or a sun-sized cap. Other materials are shaded as by "
                 "conventional (lights with extent by LTC).",
      .params = {binomial_screen_space_scale_param(),
                 binomial_remaining_count_param(),
                 {"subdivision", 0, 0, 2,
                  "quad lights cut into cells, each with its own LTC integrals, the reflecting facets split "
                  "between them by hierarchical binomial draws (the paper's fig. 9): glints take the colours "
                  "and positions of the light's parts; other lights are not cut",
                  {"none", "2x2", "4x4"},
                  /*compile_time=*/true},
                 {"light_probability", 0, 0, 1,
                  "how p's integral over a light is taken: by its own LTC (ndf-ltc: the D-only table's matrix "
                  "and magnitude, a second LTC integral per light), or by the smooth GGX lobe's LTC integral, "
                  "which the specular term needs anyway, scaled by the D-only magnitude (ggx-ltc: the paper's "
                  "cheap mode, one LTC integral per light)",
                  {"ndf-ltc", "ggx-ltc"},
                  /*compile_time=*/true},
                 {"point_light_solid_angle", 0.0f, 0.0f, 0.1f,
                  "delta lights (no extent): 0 counts facets with the material's R (p = R D(h) / D(0), as "
                  "deliot2023 and the reference); > 0 treats them as a cap of this solid angle in sr "
                  "(the paper's sun: 6.8e-5)"}},
      // The D-only LTC for p, the GGX LTC for the smooth integral (also other materials' lights).
      .tables = {"ltc-ggx", "ltc-ndf"},
      .material_kinds = {"binomial-glints"},
  };
}

GLINTLAB_REGISTER_METHOD(kneiphof2024_method, 830);

}  // namespace glintlab
