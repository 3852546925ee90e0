// Material kind `glinty` (src/scene/materials/glinty.cpp): Chermain et al.'s procedural glinty
// BRDF (glints/chermain/) with the shading point's own footprint and no anti-aliasing, the
// surface as it is (the papers' protocol for ground truth); sampled as its smooth limit, the
// Beckmann lobe of sigma (core/sampling.glsl; MIS keeps the estimate unbiased).
#include "core/brdf.glsl"
#include "core/sampling.glsl"
#include "glints/chermain/shading.glsl"
#include "lights/light_data.glsl"
#include "lobe/lobe.glsl"

GlintSurface gGlintyMaterial;  // the glinty BRDF with this point's own footprint

void glintyMaterialPrepare(inout Surface s, MaterialData m) { gGlintyMaterial = prepareGlints(s, m, false, true); }

vec3 glintyMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) {
  return glintSpecularCos(gGlintyMaterial, wo, wi, s.f0, vec2(0.0), vec2(0.0), false);
}

vec3 glintyMaterialDiffuseCos(Surface s, vec3 wi) { return diffuseCos(s.diffuse, wi); }

vec3 glintyMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
  return s.ndf == NDF_BECKMANN ? sampleBeckmannNormal(s.alpha, u) : sampleGGXVisibleNormal(wo, s.alpha, u);
}

float glintyMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
  return s.ndf == NDF_BECKMANN ? beckmannReflectionPdf(wo, wi, s.alpha) : ggxVisibleReflectionPdf(wo, wi, s.alpha);
}

Lobe glintyMaterialSmoothLobe(Surface s) { return materialLobe(s); }

vec3 glintyMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) { return glintyMaterialSpecularCos(s, wo, wi); }

float glintyMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) { return 1.0; }
