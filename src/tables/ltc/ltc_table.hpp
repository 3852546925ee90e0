#pragma once
// The layout of the ltc-ggx and ltc-ndf tables: the contract with shaders/ltc/ltc_tables.glsl
// (src/tables/ltc_ggx_table.cpp and ltc_ndf_table.cpp upload them; docs/methods.md,
// "Linearly transformed cosines").
//
// Each is a 64 x 64 x 2 array of RGBA floats, float (layer, i, j, channel) at
// ((layer * 64 + j) * 64 + i) * 4 + channel, i.e. a GL_TEXTURE_2D_ARRAY with x = i, y = j:
// * cell (i, j): roughness r = i / 63, alpha = max(r^2, kLtcAlphaMin); cos(theta_v) = 1 - (j / 63)^2
//   (the fit uses at least LtcFitSettings::cos_theta_min), so the texture coordinate of
//   (alpha, cos) is (sqrt(alpha), sqrt(1 - cos)) * 63/64 + 0.5/64;
// * layer 0: M^-1 of the fitted LTC divided by its (1,1) element, as (m00, m02, m20, m22)
//   (m_rc: row r, column c; m01 = m10 = m12 = m21 = 0): GLSL's
//   mat3(vec3(t.x, 0, t.z), vec3(0, 1, 0), vec3(t.y, 0, t.w));
// * layer 1 of ltc-ggx: (magnitude, fresnel, S, 0): magnitude = int_{l.z>0} f cos, fresnel =
//   int f cos (1 - v.h)^5, so that Schlick's F gives int f cos F = f0 magnitude + (1 - f0) fresnel;
//   S = clipped_cap_ratio(z, |F|) (ltc_sphere.hpp) on its own grid: texel (i, j) holds
//   z = 2 i / 63 - 1, |F| = j / 63;
// * layer 1 of ltc-ndf: (magnitude, total, 0, 0): magnitude = int_{l.z>0} D(h) / (4 v.h) dl,
//   total = ggx_total_ndf(alpha), the integral of D over the hemisphere of normals.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include "tables/ltc/ltc_fit.hpp"

namespace glintlab {

constexpr int kLtcTableSize = 64;
constexpr int kLtcTableLayers = 2;
/// The smallest alpha of the tables' first roughness column: the shaders' MIN_ALPHA.
constexpr double kLtcAlphaMin = 1e-4;

/// The fit behind both tables (LtcFitSettings' defaults with the table's size and alpha floor).
LtcFitSettings ltc_table_fit_settings();
/// The settings as "name=value ..." (what keys the table cache).
std::string ltc_table_settings_text(const LtcFitSettings& settings);

[[nodiscard]] constexpr std::size_t ltc_table_value_count() {
  return std::size_t{kLtcTableSize} * kLtcTableSize * kLtcTableLayers * 4;
}
/// The index of channel 0 of texel (i, j) of a layer.
[[nodiscard]] constexpr std::size_t ltc_texel(int layer, int i, int j) {
  return ((static_cast<std::size_t>(layer) * kLtcTableSize + j) * kLtcTableSize + i) * 4;
}

/// Layer 0's texel of M^-1: (m00, m02, m20, m22) / m11.
glm::vec4 pack_ltc_inverse(const glm::dmat3& m_inverse);
/// The matrix GLSL rebuilds from a layer-0 texel (with m11 = 1).
glm::dmat3 unpack_ltc_inverse(const glm::vec4& texel);

/// The table's values from a fit of its size (the fit's kind decides the layer-1 content).
std::vector<float> ltc_table_values(const LtcFit& fit);
/// Fits and lays out a table: what the table framework's generator calls.
std::vector<float> generate_ltc_table(LtcTargetKind kind, const LtcProgressFn& progress = {});

}  // namespace glintlab
