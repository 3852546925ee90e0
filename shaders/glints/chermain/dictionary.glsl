// The dictionary of multiscale 1D slope marginals (src/tables/glint_dictionary/glint_dictionary.hpp), the table
// glint-dictionary (src/tables/glint_dictionary_table.cpp; its unit TABLE_UNIT_GLINT_DICTIONARY
// comes from the table registry): marginal k of level l lives in channel k % 3 of layer
// l * GLINT_MARGINALS / 3 + k / 3; texel x holds the density at |slope| = (x + 1/2) / texels *
// GLINT_SLOPE_RANGE, so the texture coordinate of a slope s is |s| / GLINT_SLOPE_RANGE. The
// constants GLINT_MARGINALS, GLINT_LEVELS, GLINT_DICT_SIGMA (sigma_dict = alpha_dict / sqrt 2) and
// GLINT_SLOPE_RANGE (4 sigma_dict) are the generator's settings, declared by the table
// (src/tables/glint_dictionary_table.cpp) and defined in the generated contract.
#include "generated/gpu_contract.glsl"

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
