// Method `chermain2020`: the procedural glinty BRDF of Chermain et al. 2020 (real-time, no
// anti-aliasing of the half vector, no slope correlation). Materials without glints are shaded
// as by `conventional`. Lights with extent: the light's half-vector region as the kernel of the
// dictionary lookups, or the light as a point at its centre (parameter light_extent).
// Descriptor: src/shading/methods/chermain2020.cpp; docs/methods.md#chermain2020.
#include "glints/chermain/light_kernel.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
GlintSurface gGlint;
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
  gGlint = prepareGlints(s, materials[uMaterial], param_lean == LEAN_ON, false);  // 2020: no correlation
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
  vec3 l, irradiance;
  centreLightIncidence(L, s.position, l, irradiance);
  vec2 dx = vec2(0.0), dy = vec2(0.0);
  // Lights with extent: the light's half-vector region is the kernel of the filtered lookups
  // (glints/chermain/light_kernel.glsl); delta lights keep the unfiltered ones. Both constant.
  bool lightKernel = param_light_extent == LIGHT_EXTENT_HALF_VECTOR_KERNEL && lightHasExtent(L);
  if (lightKernel) addLightRegionToKernel(s, L, l, dx, dy);
  return shadeGlints(s, gGlint, l, irradiance, dx, dy, lightKernel);
#else
  return shadeLobe(s, L, materialSmoothLobe(s));
#endif
}
