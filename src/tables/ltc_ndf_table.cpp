// The D-only LTC table (Kneiphof & Klein 2024's dedicated fit, made by our own fitter,
// src/tables/ltc/ltc_fit.hpp): the lobe D(h) / (4 v.h) with no shadowing and no cosine, what glint
// counting integrates over a light, with its magnitude and the total NDF (layout:
// src/tables/ltc/ltc_table.hpp). Read by shaders/ltc/ltc_tables.glsl (uLtcNdf).
#include "tables/ltc_texture.hpp"

namespace glintlab {

Table ltc_ndf_table() {
  return {
      .source =
          {
              .id = "ltc-ndf",
              .title = "LTC fit of the GGX NDF lobe D/(4 v.h) for glint counting; magnitude, total NDF",
              .version = 1,
              .settings = "target=ndf " + ltc_table_settings_text(ltc_table_fit_settings()),
              .value_count = ltc_table_value_count(),
              .generate = [](const TableProgressFn& progress) { return generate_ltc_table(LtcTargetKind::Ndf, progress); },
              .check = check_ltc_table,
          },
      .sampler = "uLtcNdf",
      .gpu_bytes = ltc_table_gpu_bytes(),
      .upload = upload_ltc_table,
      .glsl_constants = ltc_table_glsl_constants(),
  };
}

}  // namespace glintlab
