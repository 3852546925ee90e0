// The glint dictionary as a precomputed table: the multiscale 1D slope marginals of Chermain et
// al. 2020 (tables/glint_dictionary/glint_dictionary.hpp, our own generator), read by the glinty BRDF
// (shaders/glints/chermain/dictionary.glsl) in chermain2020, chermain2021, the reference and the
// glint-cell diagnostics.
//
// On the GPU: a GL_TEXTURE_1D_ARRAY of RGB16F, three marginals per texel (marginal k in channel
// k % 3 of layer level * N/3 + k / 3), with a full mip chain made by averaging texel pairs (each
// mip level still integrates to 1) and mirrored repeat along s, so that a filtered lookup near
// |slope| = 0 sees the even function (Chermain et al. 2021, sec. 6.1).
#include <bit>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gl/context.hpp"
#include "tables/glint_dictionary/glint_dictionary.hpp"
#include "tables/table.hpp"

namespace glintlab {
namespace {

// The defaults are the paper's dictionary; its GLSL reads them as the constants below.
const GlintDictionarySettings kSettings{};
constexpr std::size_t kTexelBytes = 6;  // RGB16F

std::string settings_text(const GlintDictionarySettings& st) {
  char text[160];
  std::snprintf(text, sizeof text, "marginals=%d levels=%d texels=%d alpha=%.9g lobe_sigma=%.9g seed=%u", st.marginals,
                st.levels, st.texels, static_cast<double>(st.alpha), static_cast<double>(st.lobe_sigma), st.seed);
  return text;
}

int layers(const GlintDictionarySettings& st) { return st.levels * (st.marginals / 3); }

gl::Texture upload(const GlintDictionary& dictionary) {
  const GlintDictionarySettings& st = dictionary.settings();
  const int per_level = st.marginals / 3;
  const int layer_count = layers(st);
  const int mips = std::countr_zero(static_cast<unsigned>(st.texels)) + 1;

  // Level 0 of the mip chain: RGB texels, layer-major.
  std::vector<float> rgb(static_cast<std::size_t>(layer_count) * st.texels * 3);
  for (int level = 0; level < st.levels; ++level)
    for (int k = 0; k < st.marginals; ++k) {
      const auto table = dictionary.table(level, k);
      const std::size_t layer = static_cast<std::size_t>(level) * per_level + k / 3;
      for (int x = 0; x < st.texels; ++x) rgb[(layer * st.texels + x) * 3 + k % 3] = table[static_cast<std::size_t>(x)];
    }

  gl::Texture texture = gl::make_texture(GL_TEXTURE_1D_ARRAY);
  const GLuint id = texture.id();
  glTextureStorage2D(id, mips, GL_RGB16F, st.texels, layer_count);
  int width = st.texels;
  for (int mip = 0; mip < mips; ++mip) {
    glTextureSubImage2D(id, mip, 0, 0, width, layer_count, GL_RGB, GL_FLOAT, rgb.data());
    // Next level: the average of texel pairs (a box filter that keeps 2 ds sum = 1).
    const int half = width / 2;
    std::vector<float> next(static_cast<std::size_t>(layer_count) * std::max(half, 1) * 3);
    for (int layer = 0; layer < layer_count && half > 0; ++layer)
      for (int x = 0; x < half; ++x)
        for (int c = 0; c < 3; ++c) {
          const auto src = [&](int t) { return rgb[(static_cast<std::size_t>(layer) * width + t) * 3 + c]; };
          next[(static_cast<std::size_t>(layer) * half + x) * 3 + c] = 0.5f * (src(2 * x) + src(2 * x + 1));
        }
    rgb = std::move(next);
    width = half;
  }
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  check_gl("uploading the glint dictionary");
  return texture;
}

}  // namespace

Table glint_dictionary_table() {
  return {
      .source =
          {
              .id = "glint-dictionary",
              .title = "glint dictionary (multiscale 1D slope marginals, Chermain et al. 2020)",
              .version = 1,
              .settings = settings_text(kSettings),
              .value_count = GlintDictionary::value_count(kSettings),
              .generate = [](const TableProgressFn& progress) {
                return GlintDictionary::generate(kSettings, progress).release();
              },
              .check = [](std::span<const float> values) -> std::string {
                for (float v : values)
                  if (!(std::isfinite(v) && v >= 0.0f)) return "a density is negative or not finite";
                return "";
              },
          },
      .sampler = "uGlintDictionary",
      .gpu_bytes = mip_chain_bytes_1d(kSettings.texels, layers(kSettings), kTexelBytes),
      .upload = [](std::span<const float> values) {
        return upload(GlintDictionary::from_data(kSettings, std::vector<float>(values.begin(), values.end())));
      },
      // The layout shaders/glints/chermain/dictionary.glsl addresses and the distribution
      // glints/chermain/ndf.glsl scales to the material's roughness.
      .glsl_constants = {TableConstant::of_int("GLINT_MARGINALS", kSettings.marginals),
                         TableConstant::of_int("GLINT_LEVELS", kSettings.levels),
                         TableConstant::of_float("GLINT_DICT_SIGMA", kSettings.sigma()),
                         TableConstant::of_float("GLINT_SLOPE_RANGE", kSettings.slope_range())},
  };
}

}  // namespace glintlab
