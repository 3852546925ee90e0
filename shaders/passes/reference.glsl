// Ground truth for one sub-pixel sample: the material's exact BRDF at this sub-pixel, lights with
// extent integrated by multiple importance sampling of the light and the BRDF (power heuristic,
// Veach 1997) with low-discrepancy samples stratified over the pixel's k x k sub-pixels.
// Never uses the approximations of any method. Included in place of a method module.
#include "common/brdf.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/sampling.glsl"
#include "common/surface.glsl"
#if MATERIAL_GLINTS
#include "common/glint_shading.glsl"
GlintSurface gGlint;  // the glinty BRDF with this sub-pixel's own footprint, no anti-aliasing
#elif MATERIAL_BINOMIAL_GLINTS
#include "common/binomial_shading.glsl"
BinomialSurface gBinomial;  // the binomial glints with this sub-pixel's own footprint
// Cells one sub-pixel across (Shannon's limit at the sub-pixel scale; the pixel averages them).
const float REFERENCE_SCREEN_SPACE_SCALE = 1.0;
#endif

// Below this alpha the material is treated as a perfect mirror (a delta BRDF).
const float REFERENCE_MIRROR_ALPHA = 1e-4;

uint gReferenceLightIndex = 0u;

// Ground truth takes the surface as it is; a glinty material's patch-SDF (or binomial grids) is
// that of the sub-pixel's footprint (the papers' protocol).
void prepareSurface(inout Surface s) {
#if MATERIAL_GLINTS
  gGlint = prepareGlints(s, materials[uMaterial], false, true);
#elif MATERIAL_BINOMIAL_GLINTS
  gBinomial = prepareBinomialGlints(s, materials[uMaterial], REFERENCE_SCREEN_SPACE_SCALE);
#endif
}

// The material's specular BRDF times the cosine.
vec3 materialSpecularCos(Surface s, vec3 wo, vec3 wi) {
#if MATERIAL_GLINTS
  return glintSpecularCos(gGlint, wo, wi, s.f0, vec2(0.0), vec2(0.0), false);
#elif MATERIAL_BINOMIAL_GLINTS
  return binomialSpecularCos(gBinomial, wo, wi, s.f0, s.alpha, REMAINING_LOGNORMAL);
#else
  return specularCos(s.ndf, wo, wi, s.alpha, s.f0);
#endif
}

// Solid-angle density of the BRDF sampling strategy below (common/sampling.glsl, tested by
// chi-square against the samplers in tests/gl/test_sampling.cpp).
float brdfSamplePdf(Surface s, vec3 wo, vec3 wi) {
  return s.ndf == NDF_BECKMANN ? beckmannReflectionPdf(wo, wi, s.alpha) : ggxVisibleReflectionPdf(wo, wi, s.alpha);
}

// Power-heuristic weight of a strategy of density `pdf` against one of density `other` (Veach
// 1997), as 1 / (1 + r^2) with r = other / pdf, finite for any pair with pdf > 0.
float powerHeuristic(float pdf, float other) {
  float r = other / pdf;
  return 1.0 / (1.0 + r * r);
}

vec3 sampleBrdfNormal(Surface s, vec3 wo, vec2 u) {
  return s.ndf == NDF_BECKMANN ? sampleBeckmannNormal(s.alpha, u) : sampleGGXVisibleNormal(wo, s.alpha, u);
}

Radiance shadeLight(Surface s, LightData L) {
  uint lightIndex = gReferenceLightIndex++;
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;

  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    return Radiance(diffuseCos(s.diffuse, wi) * irradiance, materialSpecularCos(s, wo, wi) * irradiance);
  }

  int k = uTarget.z;
  ivec2 global = uTile.xy + ivec2(gl_FragCoord.xy);
  ivec2 pixel = global / k;
  ivec2 sub = global - pixel * k;
  uint n = uint(max(uTile.z, 1));
  uint first = uint(sub.y * k + sub.x) * n;  // this sub-pixel's slice of the pixel's sequence
  uint seed = hash3(uvec3(uvec2(pixel), lightIndex * 9781u + uint(uTile.w)));
  vec2 rotLight = hashToUnit2(seed);
  vec2 rotBrdf = hashToUnit2(pcgHash(seed + 1u));
  vec3 radiance = lightRadiance(L);
  bool mirror = max(s.alpha.x, s.alpha.y) < REFERENCE_MIRROR_ALPHA;  // never glinty: sigma >= 0.005, binomial alpha >= 0.01

  for (uint j = 0u; j < n; ++j) {
    vec3 dir;
    float dist, pdfLight;
    if (sampleLightDirection(L, s.position, r2Point(first + j, rotLight), dir, dist, pdfLight) && pdfLight > 0.0) {
      vec3 wi = toLocal(s, dir);
      if (wi.z > 0.0) {
        result.diffuse += diffuseCos(s.diffuse, wi) * radiance / pdfLight;
        if (!mirror) {
          float w = powerHeuristic(pdfLight, brdfSamplePdf(s, wo, wi));
          result.specular += materialSpecularCos(s, wo, wi) * radiance * (w / pdfLight);
        }
      }
    }
    if (!mirror) {
      vec3 h = sampleBrdfNormal(s, wo, r2Point(first + j, rotBrdf));
      vec3 wi = reflect(-wo, h);
      vec3 dirWorld = toWorld(s, wi);
      if (wi.z > 0.0 && lightHit(L, s.position, dirWorld, dist)) {
        float pdfBrdf = brdfSamplePdf(s, wo, wi);
        float pdfL = lightPdf(L, s.position, dirWorld, dist);
        if (pdfBrdf > 0.0) result.specular += materialSpecularCos(s, wo, wi) * radiance * (powerHeuristic(pdfBrdf, pdfL) / pdfBrdf);
      }
    }
  }
  result.diffuse /= float(n);
  result.specular /= float(n);
  if (mirror) {
    float dist;
    vec3 r = reflect(-s.view, s.normal);
    if (lightHit(L, s.position, r, dist)) result.specular = fresnelSchlick(s.f0, wo.z) * radiance;
  }
  return result;
}
