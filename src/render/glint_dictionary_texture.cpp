#include "render/glint_dictionary_texture.hpp"

#include <bit>
#include <vector>

#include "gl/context.hpp"

namespace glintlab {

GlintDictionaryTexture upload_glint_dictionary(const GlintDictionary& dictionary) {
  const GlintDictionarySettings& st = dictionary.settings();
  const int per_level = st.marginals / 3;
  const int layers = st.levels * per_level;
  const int mips = std::countr_zero(static_cast<unsigned>(st.texels)) + 1;

  // Level 0 of the mip chain: RGB texels, layer-major.
  std::vector<float> rgb(static_cast<std::size_t>(layers) * st.texels * 3);
  for (int level = 0; level < st.levels; ++level)
    for (int k = 0; k < st.marginals; ++k) {
      const auto table = dictionary.table(level, k);
      const std::size_t layer = static_cast<std::size_t>(level) * per_level + k / 3;
      for (int x = 0; x < st.texels; ++x) rgb[(layer * st.texels + x) * 3 + k % 3] = table[static_cast<std::size_t>(x)];
    }

  GlintDictionaryTexture result;
  result.texture = gl::make_texture(GL_TEXTURE_1D_ARRAY);
  const GLuint id = result.texture.id();
  glTextureStorage2D(id, mips, GL_RGB16F, st.texels, layers);
  int width = st.texels;
  for (int mip = 0; mip < mips; ++mip) {
    glTextureSubImage2D(id, mip, 0, 0, width, layers, GL_RGB, GL_FLOAT, rgb.data());
    result.bytes_with_mips += static_cast<std::size_t>(width) * layers * 6;
    if (mip == 0) result.bytes_base = result.bytes_with_mips;
    // Next level: the average of texel pairs (a box filter that keeps 2 ds sum = 1).
    const int half = width / 2;
    std::vector<float> next(static_cast<std::size_t>(layers) * std::max(half, 1) * 3);
    for (int layer = 0; layer < layers && half > 0; ++layer)
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
  return result;
}

}  // namespace glintlab
