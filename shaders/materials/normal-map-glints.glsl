// Material kind `normal-map-glints` (src/scene/materials/normal_map_glints.cpp): Yan et al. 2016's
// microsurface at this point of the map, exactly (glints/normal-map/surface.glsl): the map's
// normal at the point is the mean of the projected normals, and the BRDF lives in the macro frame,
// so the frame goes back to the vertex normal (the map's x, y are that frame's). Sampled by the
// projected normal's own Gaussian.
#include "core/brdf.glsl"
#include "core/surface.glsl"
#include "glints/normal-map/surface.glsl"
#include "lights/light_data.glsl"
#include "lobe/lobe.glsl"

NormalGlintPoint gNormalMapGlintsMaterial;  // this point of the map (in the macro frame)

void normalMapGlintsMaterialPrepare(inout Surface s, MaterialData m) {
  gNormalMapGlintsMaterial = normalGlintPoint(s.mappedNormal, m);
  setShadingNormal(s, s.vertexNormal);
}

vec3 normalMapGlintsMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) {
  return normalGlintSpecularCos(gNormalMapGlintsMaterial, wo, wi, s.f0);
}

// Lambert in the macro frame sees the map's normal, as every method's normal-mapped Lambert does.
vec3 normalMapGlintsMaterialDiffuseCos(Surface s, vec3 wi) {
  return s.diffuse * (INV_PI * max(dot(gNormalMapGlintsMaterial.normal, wi), 0.0));
}

vec3 normalMapGlintsMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
  return sampleNormalGlintNormal(gNormalMapGlintsMaterial, u);
}

float normalMapGlintsMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
  return normalGlintReflectionPdf(gNormalMapGlintsMaterial, wo, wi);
}

Lobe normalMapGlintsMaterialSmoothLobe(Surface s) { return materialLobe(s); }

vec3 normalMapGlintsMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) {
  return normalMapGlintsMaterialSpecularCos(s, wo, wi);
}

float normalMapGlintsMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) {
  return 1.0;
}
