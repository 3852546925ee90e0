#pragma once
// The glint dictionary on the GPU (shaders/common/glint_dictionary.glsl): a GL_TEXTURE_1D_ARRAY of
// RGB16F, three marginals per texel (marginal k in channel k % 3 of layer level * N/3 + k / 3),
// with a full mip chain made by averaging texel pairs (each mip level still integrates to 1) and
// mirrored repeat along s, so that a filtered lookup near |slope| = 0 sees the even function
// (Chermain et al. 2021, sec. 6.1).
#include <cstddef>

#include "gl/objects.hpp"
#include "glints/glint_dictionary.hpp"

namespace glintlab {

struct GlintDictionaryTexture {
  gl::Texture texture;
  std::size_t bytes_base = 0;      ///< texels of level 0 of every layer, 6 bytes each
  std::size_t bytes_with_mips = 0; ///< with the whole mip chain
};

GlintDictionaryTexture upload_glint_dictionary(const GlintDictionary& dictionary);

}  // namespace glintlab
