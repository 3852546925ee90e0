// Material kind `point-process-glints` (src/scene/materials/point_process_glints.cpp): the glinty
// NDF of Kemppinen et al. 2025 (glints/point-process/) with the shading point's own footprint: the
// sub-pixel's in the reference (the papers' protocol, as for `glinty`), the pixel's in the method.
// Sampled by the NDF's own constant-time sampler, with its exact density.
#include "core/brdf.glsl"
#include "glints/point-process/shading.glsl"
#include "lights/light_data.glsl"
#include "lobe/lobe.glsl"

PointProcessFootprint gPointProcessGlintsMaterial;  // the glints with this point's own footprint

void pointProcessGlintsMaterialPrepare(inout Surface s, MaterialData m) {
  gPointProcessGlintsMaterial = preparePointProcessGlints(s, m, 1.0);
}

vec3 pointProcessGlintsMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) {
  return pointProcessSpecularCos(gPointProcessGlintsMaterial, wo, wi, s.f0);
}

vec3 pointProcessGlintsMaterialDiffuseCos(Surface s, vec3 wi) { return diffuseCos(s.diffuse, wi); }

vec3 pointProcessGlintsMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
  return pointProcessSampleNormal(gPointProcessGlintsMaterial, u);
}

float pointProcessGlintsMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
  return pointProcessReflectionPdf(gPointProcessGlintsMaterial, wo, wi);
}

Lobe pointProcessGlintsMaterialSmoothLobe(Surface s) { return materialLobe(s); }

vec3 pointProcessGlintsMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) {
  return pointProcessGlintsMaterialSpecularCos(s, wo, wi);
}

float pointProcessGlintsMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) {
  return 1.0;
}
