// Method `tokuyoshi`: projected-space NDF filtering (Tokuyoshi & Kaplanyan 2019, 2021).
// Descriptor: src/shading/methods/tokuyoshi.cpp; docs/methods.md#tokuyoshi.
#include "lobe/footprint_filtering.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  // Derivatives first, in uniform control flow: the projected half vector towards the light's centre.
  vec2 h = projectedHalfVector(s, lightCentreDirection(L, s.position));
  Lobe lobe = tokuyoshiLobe(materialSmoothLobe(s), dFdxFine(h), dFdyFine(h), param_sigma2, param_kappa);
  return shadeLobe(s, L, lobe, param_area_lights);
}
