// The `normal-map-glints` kind as a method's footprint NDF, for the path tracer's backends
// `path:<method>` (src/render/path_reference.hpp): instead of the microsurface at the hit (the kind's
// own module, materials/normal-map-glints.glsl, which the ground truth evaluates), the NDF of the
// hit's footprint as the method in the $METHOD slot gives it (yan2016: the P-NDF summed over the
// map's elements; deng2022: the compressed pyramid's queries), evaluated, importance sampled and
// integrated over environment lobes as the paper's offline renderer does (Deng et al. 2022, secs.
// 5.1, 5.2, 5.4). The method's module, compiled with METHOD_AS_FOOTPRINT_NDF, defines
//   void normalGlintsPrepareFootprint(inout Surface s);  // the footprint at this point
//   float normalGlintsDensity(vec2 s);                  // its P over projected half vectors
//   NdfSample normalGlintsSampleNdf(uint seed, vec2 u);  // a sample of P over its mass ...
//   float normalGlintsSamplePdf(vec2 s);                 // ... and the density of those samples
// and gMaskingAlpha, gDiffuseNormal. The material interface's functions are these with the prefix
// normalMapGlintsFootprintMaterial (forwarded by the generated module, src/render/shader_contract.cpp).
#define METHOD_AS_FOOTPRINT_NDF
// The path tracer queries the footprint's NDF per hit up to 6 times per light sample of each light
// (the light's sample: its density and integrand; the material's: its sample's two passes, density
// and integrand), once per lobe and cone, and 4 times for the bounce: the element budget
// (llvmpipe's 65535 loop iterations per invocation) is shared by them all, so that more light
// samples per sub-pixel sum smaller subsets of a large footprint's elements.
// The method's element budget (max_elements) is each query's, within that share.
int footprintExtraQueries();
#define NORMAL_GLINTS_EXTRA_QUERIES footprintExtraQueries()
#define POSITION_NORMAL_BUDGET_PER_QUERY
#include "$METHOD"
int footprintExtraQueries() {
  const int lights = positionNormalLightCount();
  return lights * 6 * max(frame.tile.z, 1) + environmentLobeCount * ENVIRONMENT_LOBE_CONES + 4 - lights;
}
// The path tracer shades environments by the method's lobes where it fitted any (passes/path_direct.comp).
#define MATERIAL_ENVIRONMENT_LOBES

void normalMapGlintsFootprintMaterialPrepare(inout Surface s, MaterialData m) { normalGlintsPrepareFootprint(s); }

// F G2 P(h.xy) / (4 wo.z): glints/normal-map/shading.glsl's specular term at the footprint's P.
vec3 normalMapGlintsFootprintMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) {
  const vec3 m = wo + wi;
  if (wi.z <= 0.0 || dot(m, m) <= 0.0) return vec3(0.0);
  const vec3 h = normalize(m);
  return h.z > 0.0 ? normalGlintsSpecularCos(wo, wi, h, normalGlintsDensity(h.xy), s.f0, gMaskingAlpha) : vec3(0.0);
}

vec3 normalMapGlintsFootprintMaterialDiffuseCos(Surface s, vec3 wi) {
  return normalGlintsDiffuseCos(s.diffuse, gDiffuseNormal, wi);
}

// The sampler's discrete choices (a probe, an element, a block) take their uniforms from a seed
// hashed from u's bits: the interface passes one point of the reference's low-discrepancy
// sequence, and a hash of it is independent of its value.
vec3 normalMapGlintsFootprintMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
  const uint seed = hash3(uvec3(floatBitsToUint(u.x), floatBitsToUint(u.y), 0x2545f491u));
  const NdfSample x = normalGlintsSampleNdf(seed, u);
  const float s2 = dot(x.s, x.s);
  return x.pdf > 0.0 && s2 < 1.0 ? vec3(x.s, sqrt(1.0 - s2)) : vec3(0.0);
}

// The samples' density over s is p(s); over normals p(s) h.z (ds = h.z dw_h); over reflected
// directions that over 4 wo.h (Walter et al. 2007, eq. 14).
float normalMapGlintsFootprintMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
  const vec3 m = wo + wi;
  if (dot(m, m) <= 0.0) return 0.0;
  const vec3 h = normalize(m);
  const float oh = dot(wo, h);
  if (oh <= 0.0 || h.z <= 0.0) return 0.0;
  return normalGlintsSamplePdf(h.xy) * h.z / (4.0 * oh);
}

Lobe normalMapGlintsFootprintMaterialSmoothLobe(Surface s) { return materialLobe(s); }

vec3 normalMapGlintsFootprintMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) {
  return normalMapGlintsFootprintMaterialSpecularCos(s, wo, wi);
}

float normalMapGlintsFootprintMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight,
                                                  vec2 rotBrdf) {
  return 1.0;
}
