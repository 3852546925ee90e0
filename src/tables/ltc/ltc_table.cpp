#include "tables/ltc/ltc_table.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/matrix.hpp>

#include "tables/ltc/ltc_sphere.hpp"

namespace glintlab {

LtcFitSettings ltc_table_fit_settings() {
  LtcFitSettings settings;
  settings.size = kLtcTableSize;
  settings.alpha_min = kLtcAlphaMin;
  return settings;
}

std::string ltc_table_settings_text(const LtcFitSettings& s) {
  char text[256];
  std::snprintf(text, sizeof text,
                "size=%d samples=%d moment_samples=%d alpha_min=%.9g cos_theta_min=%.9g max_evaluations=%d "
                "tolerance=%.9g",
                s.size, s.samples, s.moment_samples, s.alpha_min, s.cos_theta_min, s.max_evaluations, s.tolerance);
  return text;
}

glm::vec4 pack_ltc_inverse(const glm::dmat3& m) {
  // glm is column-major: m[c][r] is row r, column c.
  const double m11 = m[1][1];
  return glm::vec4(m[0][0] / m11, m[2][0] / m11, m[0][2] / m11, m[2][2] / m11);
}

glm::dmat3 unpack_ltc_inverse(const glm::vec4& t) {
  // mat3(vec3(t.x, 0, t.z), vec3(0, 1, 0), vec3(t.y, 0, t.w)): the same columns as in GLSL.
  return glm::dmat3(glm::dvec3(t.x, 0.0, t.z), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(t.y, 0.0, t.w));
}

std::vector<float> ltc_table_values(const LtcFit& fit) {
  if (fit.settings.size != kLtcTableSize)
    throw std::invalid_argument("LTC table: the fit has " + std::to_string(fit.settings.size) + " cells a side; the table " +
                                std::to_string(kLtcTableSize));
  std::vector<float> values(ltc_table_value_count(), 0.0f);
  auto put = [&](int layer, int i, int j, glm::vec4 texel) {
    for (int c = 0; c < 4; ++c) values[ltc_texel(layer, i, j) + static_cast<std::size_t>(c)] = texel[c];
  };
  const double last = kLtcTableSize - 1;
  for (int j = 0; j < kLtcTableSize; ++j)
    for (int i = 0; i < kLtcTableSize; ++i) {
      const LtcCell& cell = fit.cell(i, j);
      put(0, i, j, pack_ltc_inverse(glm::inverse(cell.matrix)));
      const auto magnitude = static_cast<float>(cell.moments.magnitude);
      if (fit.kind == LtcTargetKind::Ggx) {
        const double sphere = clipped_cap_ratio(2.0 * i / last - 1.0, j / last);
        put(1, i, j, {magnitude, static_cast<float>(cell.moments.fresnel), static_cast<float>(sphere), 0.0f});
      } else {
        put(1, i, j, {magnitude, static_cast<float>(ggx_total_ndf(ltc_grid_alpha(i, fit.settings))), 0.0f, 0.0f});
      }
    }
  return values;
}

std::vector<float> generate_ltc_table(LtcTargetKind kind, const LtcProgressFn& progress) {
  return ltc_table_values(fit_ltc_grid(kind, ltc_table_fit_settings(), progress));
}

}  // namespace glintlab
