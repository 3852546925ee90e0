// The split-sum's second factor as a precomputed table (Karis 2013, "Real Shading in Unreal
// Engine 4"): the directional albedo of the specular BRDF of shaders/core/brdf.glsl, GGX and
// Beckmann, as E = f0 A + B (our own quadrature, src/tables/dfg/dfg.hpp, which has the layout).
// Read by shaders/lobe/dfg.glsl (uDfg).
//
// On the GPU: a GL_TEXTURE_2D of RGBA32F, kDfgTableSize^2, no mips, linear filtering and clamped
// to the edge: the texel centres hold the grid's values, so a lookup at (cos_o, sqrt(alpha))
// interpolates between grid points and holds the edge values beyond them.
#include <cmath>

#include "gl/context.hpp"
#include "tables/dfg/dfg.hpp"
#include "tables/table.hpp"

namespace glintlab {
namespace {

constexpr std::size_t kDfgTexelBytes = 16;  // RGBA32F

gl::Texture upload(std::span<const float> values) {
  gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  const GLuint id = texture.id();
  glTextureStorage2D(id, 1, GL_RGBA32F, kDfgTableSize, kDfgTableSize);
  glTextureSubImage2D(id, 0, 0, 0, kDfgTableSize, kDfgTableSize, GL_RGBA, GL_FLOAT, values.data());
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl("uploading the dfg table");
  return texture;
}

/// Why values read back from the cache cannot be the table, or "": each term is finite and
/// non-negative, and their sum, an albedo, at most 1 (to the quadrature's error).
std::string check(std::span<const float> values) {
  for (std::size_t k = 0; k < values.size(); k += 2) {
    const float a = values[k], b = values[k + 1];
    if (!std::isfinite(a) || !std::isfinite(b) || a < 0 || b < 0) return "a term is negative or not finite";
    if (a + b > 1.001f) return "an albedo A + B exceeds 1";
  }
  return "";
}

}  // namespace

Table dfg_table() {
  constexpr std::size_t bytes = dfg_table_value_count() / 4 * kDfgTexelBytes;
  return {
      .source =
          {
              .id = "dfg",
              .title = "Split-sum directional albedo f0 A + B of GGX and Beckmann with Smith G2 (Karis 2013)",
              .version = 1,
              .settings = dfg_table_settings(),
              .value_count = dfg_table_value_count(),
              .generate = [](const TableProgressFn& progress) { return generate_dfg_table(progress); },
              .check = check,
          },
      .sampler = "uDfg",
      .gpu_bytes = {bytes, bytes},
      .upload = upload,
      .glsl_constants = {TableConstant::of_int("DFG_TABLE_SIZE", kDfgTableSize)},
  };
}

}  // namespace glintlab
