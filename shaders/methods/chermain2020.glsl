// Method `chermain2020`: the procedural glinty BRDF of Chermain et al. 2020 (real-time, no
// anti-aliasing of the half vector, no slope correlation). Materials without glints are shaded
// as by `conventional`. Descriptor: src/shading/methods/chermain2020.cpp; docs/methods.md#chermain2020.
#include "common/glint_shading.glsl"

#if MATERIAL_GLINTS
GlintSurface gGlint;
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_GLINTS
  gGlint = prepareGlints(s, materials[uMaterial], param_lean > 0.5, false);  // 2020: no correlation
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_GLINTS
  vec3 l, irradiance;
  centreLightIncidence(L, s.position, l, irradiance);
  return shadeGlints(s, gGlint, l, irradiance, vec2(0.0), vec2(0.0), false);
#else
  return shadeLobe(s, L, materialLobe(s));
#endif
}
