// The specular LTC table (Heitz, Dupuy, Hill, Neubelt 2016), our own fit (src/tables/ltc/ltc_fit.hpp) of
// GGX with height-correlated Smith shadowing and the cosine, with its magnitude, Schlick Fresnel
// term and the horizon-clipped sphere form factor (layout: src/tables/ltc/ltc_table.hpp). Read by
// shaders/ltc/ltc_tables.glsl (uLtcGgx).
#include "tables/ltc_texture.hpp"

namespace glintlab {

Table ltc_ggx_table() {
  return {
      .source =
          {
              .id = "ltc-ggx",
              .title = "LTC fit of GGX with Smith G2 and the cosine; magnitude, Fresnel, clipped sphere (Heitz et al. 2016)",
              .version = 1,
              .settings = "target=ggx " + ltc_table_settings_text(ltc_table_fit_settings()),
              .value_count = ltc_table_value_count(),
              .generate = [](const TableProgressFn& progress) { return generate_ltc_table(LtcTargetKind::Ggx, progress); },
              .check = check_ltc_table,
          },
      .sampler = "uLtcGgx",
      .gpu_bytes = ltc_table_gpu_bytes(),
      .upload = upload_ltc_table,
      .glsl_constants = ltc_table_glsl_constants(),
  };
}

}  // namespace glintlab
