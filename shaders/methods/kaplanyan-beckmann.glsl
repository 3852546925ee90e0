// Method `kaplanyan-beckmann`: NDF filtering over the pixel footprint in slope space (Kaplanyan et al. 2016):
// Beckmann NDF convolved with the footprint's full covariance, R' = R + 2C.
// Descriptor: src/shading/methods/kaplanyan-beckmann.cpp; docs/methods.md#kaplanyan-beckmann.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#include "lobe/footprint_filtering.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  // Derivatives first, in uniform control flow: the slope-space half vector towards the light's
  // centre, differenced across the pixel quad.
  vec2 h = slopeHalfVector(s, lobeLightDirection(s, L));
  Lobe lobe = kaplanyanBeckmannLobe(materialSmoothLobe(s), dFdxFine(h), dFdyFine(h), param_fp_max);
  return shadeLobe(s, L, lobe, param_area_lights);
}
