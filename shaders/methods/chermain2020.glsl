// Method `chermain2020`: the procedural glinty BRDF of Chermain et al. 2020 (real-time, no
// anti-aliasing of the half vector, no slope correlation). Materials without glints are shaded
// as by `conventional`. Descriptor: src/shading/methods/chermain2020.cpp; docs/methods.md#chermain2020.
#include "common/glint_shading.glsl"

uniform float param_mirror_alpha;
uniform float param_lean;

#if MATERIAL_GLINTS
GlintSurface gGlint;
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_GLINTS
  if (param_lean > 0.5) combineWithNormalMapSlopes(s);
  MaterialData m = materials[uMaterial];
  gGlint = glintSurface(s, m.glints, m.diffuse_tiling.a, 0.0);  // the 2020 model has no correlation
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_GLINTS
  vec3 l, irradiance;
  glintLightIncidence(L, s.position, l, irradiance);
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance,
                  glintSpecularCos(gGlint, wo, wi, s.f0, vec2(0.0), vec2(0.0), false) * irradiance);
#else
  return shadeLobe(s, L, materialLobe(s), param_mirror_alpha);
#endif
}
