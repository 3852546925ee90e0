#pragma once
// The texture both LTC tables live in (src/tables/ltc/ltc_table.hpp has the layout): a
// GL_TEXTURE_2D_ARRAY of RGBA32F, 64 x 64 x 2, no mips, linear filtering and clamped to the edge,
// so that lookups at the cell centres (uv * 63/64 + 0.5/64) interpolate between cells only.
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "tables/ltc/ltc_table.hpp"
#include "tables/table.hpp"

namespace glintlab {

constexpr std::size_t kLtcTexelBytes = 16;  // RGBA32F

inline TableBytes ltc_table_gpu_bytes() {
  const std::size_t bytes = ltc_table_value_count() / 4 * kLtcTexelBytes;
  return {bytes, bytes};
}

inline gl::Texture upload_ltc_table(std::span<const float> values) {
  gl::Texture texture = gl::make_texture(GL_TEXTURE_2D_ARRAY);
  const GLuint id = texture.id();
  glTextureStorage3D(id, 1, GL_RGBA32F, kLtcTableSize, kLtcTableSize, kLtcTableLayers);
  glTextureSubImage3D(id, 0, 0, 0, 0, kLtcTableSize, kLtcTableSize, kLtcTableLayers, GL_RGBA, GL_FLOAT, values.data());
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl("uploading an LTC table");
  return texture;
}

/// The layout shaders/ltc/ltc_tables.glsl addresses, the same for both tables.
inline std::vector<TableConstant> ltc_table_glsl_constants() {
  return {TableConstant::of_float("LTC_TABLE_SIZE", static_cast<float>(kLtcTableSize))};
}

/// Why values read back from the cache cannot be an LTC table, or "".
inline std::string check_ltc_table(std::span<const float> values) {
  for (float v : values)
    if (!std::isfinite(v)) return "a value is not finite";
  for (int j = 0; j < kLtcTableSize; ++j)
    for (int i = 0; i < kLtcTableSize; ++i)
      if (!(values[ltc_texel(1, i, j)] > 0.0f)) return "a magnitude is not positive";
  return "";
}

}  // namespace glintlab
