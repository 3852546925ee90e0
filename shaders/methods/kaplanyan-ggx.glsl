// Method `kaplanyan-ggx`: NDF filtering over the pixel footprint in slope space (Kaplanyan et al. 2016):
// the NDF averaged over the footprint's bounding rectangle in slope space (closed form).
// Descriptor: src/shading/methods/kaplanyan-ggx.cpp; docs/methods.md#kaplanyan-ggx.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#include "lobe/footprint_filtering.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  // Derivatives first, in uniform control flow: the slope-space half vector towards the light's
  // centre, differenced across the pixel quad.
  vec2 h = slopeHalfVector(s, lobeLightDirection(s, L));
  Lobe lobe = kaplanyanBoxLobe(materialSmoothLobe(s), dFdxFine(h), dFdyFine(h), param_fp_max);
  return shadeLobe(s, L, lobe, param_area_lights);
}
