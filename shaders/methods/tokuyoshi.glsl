// Method `tokuyoshi`: projected-space NDF filtering (Tokuyoshi & Kaplanyan 2019, 2021).
// Descriptor: src/shading/methods/tokuyoshi.cpp; docs/methods.md#tokuyoshi.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#include "lobe/footprint_filtering.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  // Derivatives first, in uniform control flow: the projected half vector towards the light's centre.
  vec2 h = projectedHalfVector(s, lobeLightDirection(s, L));
  Lobe lobe = tokuyoshiLobe(materialSmoothLobe(s), dFdxFine(h), dFdyFine(h), param_sigma2, param_kappa);
  return shadeLobe(s, L, lobe, param_area_lights);
}
