// The dictionary of multiscale 1D slope marginals (src/tables/glint_dictionary/glint_dictionary.hpp), the table
// glint-dictionary (src/tables/glint_dictionary_table.cpp; its unit TABLE_UNIT_GLINT_DICTIONARY
// comes from the table registry): marginal k of level l lives in channel k % 3 of layer
// l * GLINT_MARGINALS / 3 + k / 3; texel x holds the density at |slope| = (x + 1/2) / texels *
// GLINT_SLOPE_RANGE, so the texture coordinate of a slope s is |s| / GLINT_SLOPE_RANGE. The
// constants mirror GlintDictionarySettings' defaults (checked by tests/glsl/test_glints.cpp).
#include "generated/gpu_contract.glsl"

const int GLINT_MARGINALS = 192;
const int GLINT_LEVELS = 16;
const float GLINT_DICT_ALPHA = 0.5;
const float GLINT_DICT_SIGMA = 0.35355339;  // alpha_dict / sqrt(2)
const float GLINT_SLOPE_RANGE = 4.0 * GLINT_DICT_SIGMA;

layout(binding = TABLE_UNIT_GLINT_DICTIONARY) uniform sampler1DArray uGlintDictionary;

vec2 glintTexel(int level, int marginal, float slope) {
  return vec2(abs(slope) / GLINT_SLOPE_RANGE, float(level * (GLINT_MARGINALS / 3) + marginal / 3));
}

// P_k,l(slope): the marginal at its finest mip (Chermain et al. 2020).
float glintMarginal(int level, int marginal, float slope) {
  return textureLod(uGlintDictionary, glintTexel(level, marginal, slope), 0.0)[marginal % 3];
}

// The marginal convolved with a box of the given screen-space slope derivatives (Chermain et al.
// 2021, eq. 19): trilinear filtering over the mip chain; zero derivatives give glintMarginal.
float glintMarginalFiltered(int level, int marginal, float slope, float slopeDx, float slopeDy) {
  return textureGrad(uGlintDictionary, glintTexel(level, marginal, slope), slopeDx / GLINT_SLOPE_RANGE,
                     slopeDy / GLINT_SLOPE_RANGE)[marginal % 3];
}
