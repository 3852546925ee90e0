// Method `toksvig`: Toksvig's (2005) roughness from the length of the mip-filtered normal-map
// normal. Descriptor: src/shading/methods/toksvig.cpp; docs/methods.md#toksvig.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#define METHOD_LOBES_KEEP_ISOTROPY  // the material's alpha widened alike along both axes (lobe/lobe_shading.glsl)
#include "lobe/lobe_shading.glsl"
#include "core/fragment_inputs.glsl"  // uNormalMap
#include "lobe/roughness_filtering.glsl"

void prepareSurface(inout Surface s) {
  // Without a normal map the filtered normal has length 1 and alpha is unchanged.
  float share = magnifiedSpreadShare(s.footprint.dUVdx, s.footprint.dUVdy, vec2(normalMapSize()));
  s.alpha = toksvigAlpha(s.alpha, length(s.mappedNormal), share);
}

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, materialSmoothLobe(s), param_area_lights); }
