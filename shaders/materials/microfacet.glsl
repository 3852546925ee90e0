// Material kind `microfacet` (src/scene/materials/microfacet.cpp): the Cook-Torrance microfacet
// BRDF of the material's NDF (GGX or Beckmann), height-correlated Smith masking-shadowing and
// Schlick Fresnel, plus Lambert (core/brdf.glsl); sampled by GGX's visible normals (Heitz 2018) or
// Beckmann's NDF (core/sampling.glsl). The material interface: src/render/shader_contract.cpp.
#include "core/brdf.glsl"
#include "core/sampling.glsl"
#include "core/surface.glsl"
#include "lights/light_data.glsl"
#include "lobe/lobe.glsl"

void microfacetMaterialPrepare(inout Surface s, MaterialData m) {}

vec3 microfacetMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) { return specularCos(s.ndf, wo, wi, s.alpha, s.f0); }

vec3 microfacetMaterialDiffuseCos(Surface s, vec3 wi) { return diffuseCos(s.diffuse, wi); }

vec3 microfacetMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
  return s.ndf == NDF_BECKMANN ? sampleBeckmannNormal(s.alpha, u) : sampleGGXVisibleNormal(wo, s.alpha, u);
}

// Tested by chi-square against the samplers (tests/glsl/test_sampling.cpp).
float microfacetMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
  return s.ndf == NDF_BECKMANN ? beckmannReflectionPdf(wo, wi, s.alpha) : ggxVisibleReflectionPdf(wo, wi, s.alpha);
}

Lobe microfacetMaterialSmoothLobe(Surface s) { return materialLobe(s); }

vec3 microfacetMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) { return microfacetMaterialSpecularCos(s, wo, wi); }

float microfacetMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) {
  return 1.0;
}
