// Ground truth for one sub-pixel sample: the material's exact BRDF at this sub-pixel, lights with
// extent integrated by multiple importance sampling of the light and the BRDF (power heuristic,
// Veach 1997) with low-discrepancy samples stratified over the pixel's k x k sub-pixels.
// Never uses the approximations of any method. Included in place of a method module.
#ifndef REFERENCE_BINOMIAL_REALISATION
#define REFERENCE_BINOMIAL_REALISATION 0  // passes/reference_realisation.glsl sets it
#endif
#include "core/brdf.glsl"
#include "core/frame.glsl"
#include "lights/lights.glsl"
#include "core/sampling.glsl"
#include "core/surface.glsl"
// Included once whatever the variant: includes are expanded once, before the preprocessor drops
// a branch, so a module both branches below include must come before them.
#include "ltc/ltc_shading.glsl"
#if MATERIAL_GLINTS
#include "glints/chermain/shading.glsl"
GlintSurface gGlint;  // the glinty BRDF with this sub-pixel's own footprint, no anti-aliasing
#elif MATERIAL_BINOMIAL_GLINTS
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/light_ndf_integral.glsl"
#if REFERENCE_BINOMIAL_REALISATION
#include "glints/binomial/realisation.glsl"
#endif
BinomialSurface gBinomial;  // the binomial glints with this sub-pixel's own footprint
// Cells one sub-pixel across (Shannon's limit at the sub-pixel scale; the pixel averages them).
const float REFERENCE_SCREEN_SPACE_SCALE = 1.0;
// Samples of each strategy for the probability that a facet reflects a light with extent: p's own
// error, against quadrature over the light, is 0.5% relative on average and 7% at most wherever
// p >= 1e-4 (tests/glsl/test_glint_light_probability.cpp), far below the LTC's and the cap's.
const uint REFERENCE_GLINT_P_SAMPLES = 128u;
#elif MATERIAL_NORMAL_GLINTS
#include "glints/normal-map/surface.glsl"
NormalGlintPoint gNormalGlint;  // this sub-pixel's point of the map (in the macro frame)
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
#elif MATERIAL_NORMAL_GLINTS
  // The map's normal at this sample is the mean of the projected normals; the BRDF lives in the
  // macro frame, so the frame goes back to the vertex normal (the map's x, y are that frame's).
  gNormalGlint = normalGlintPoint(s.mappedNormal, materials[uMaterial]);
  setShadingNormal(s, s.vertexNormal);
#endif
}

// The material's specular BRDF times the cosine (binomial glints: under delta lights; lights with
// extent scale the smooth BRDF's integral by the glint factor, see glintReferenceFactor).
vec3 materialSpecularCos(Surface s, vec3 wo, vec3 wi) {
#if MATERIAL_GLINTS
  return glintSpecularCos(gGlint, wo, wi, s.f0, vec2(0.0), vec2(0.0), false);
#elif MATERIAL_BINOMIAL_GLINTS && REFERENCE_BINOMIAL_REALISATION
  return binomialRealisationSpecularCos(gBinomial, wo, wi, s.f0, s.alpha);
#elif MATERIAL_BINOMIAL_GLINTS
  return binomialSpecularCos(gBinomial, wo, wi, s.f0, s.alpha, REMAINING_LOGNORMAL);
#elif MATERIAL_NORMAL_GLINTS
  return normalGlintSpecularCos(gNormalGlint, wo, wi, s.f0);
#else
  return specularCos(s.ndf, wo, wi, s.alpha, s.f0);
#endif
}

// Solid-angle density of the BRDF sampling strategy below (core/sampling.glsl, tested by
// chi-square against the samplers in tests/glsl/test_sampling.cpp).
float brdfSamplePdf(Surface s, vec3 wo, vec3 wi) {
#if MATERIAL_NORMAL_GLINTS
  return normalGlintReflectionPdf(gNormalGlint, wo, wi);
#else
  return s.ndf == NDF_BECKMANN ? beckmannReflectionPdf(wo, wi, s.alpha) : ggxVisibleReflectionPdf(wo, wi, s.alpha);
#endif
}

vec3 sampleBrdfNormal(Surface s, vec3 wo, vec2 u) {
#if MATERIAL_NORMAL_GLINTS
  return sampleNormalGlintNormal(gNormalGlint, u);
#else
  return s.ndf == NDF_BECKMANN ? sampleBeckmannNormal(s.alpha, u) : sampleGGXVisibleNormal(wo, s.alpha, u);
#endif
}

// Lambert times the cosine; a normal-map-glints material's frame is the macro one, and its diffuse
// part sees the map's normal, as every method's normal-mapped Lambert does.
vec3 materialDiffuseCos(Surface s, vec3 wi) {
#if MATERIAL_NORMAL_GLINTS
  return s.diffuse * (INV_PI * max(dot(gNormalGlint.normal, wi), 0.0));
#else
  return diffuseCos(s.diffuse, wi);
#endif
}

// The specular BRDF times the cosine integrated over a light with extent: the material's, or the
// smooth GGX of a binomial-glints material, whose integral the glint factor then scales.
vec3 extentSpecularCos(Surface s, vec3 wo, vec3 wi) {
#if MATERIAL_BINOMIAL_GLINTS && !REFERENCE_BINOMIAL_REALISATION
  return specularCos(NDF_GGX, wo, wi, s.alpha, s.f0);
#else
  return materialSpecularCos(s, wo, wi);
#endif
}

#if MATERIAL_BINOMIAL_GLINTS
// The binomial-glints model under a light with extent (Kneiphof & Klein 2024's, without its
// approximations): the probability that a facet reflects the light, p = integral over the light of
// D(h) / (4 |l.h|) dl (above the horizon) / T, integrated numerically with
// REFERENCE_GLINT_P_SAMPLES samples of each strategy (sub-pixel `sub` of k^2 takes its slice of
// the pixel's sequence), then the glint factor at the half vector towards the light's centre, as
// the method draws it.
float glintReferenceFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) {
  float integral = lightNdfIntegral(s, L, wo, sub * REFERENCE_GLINT_P_SAMPLES, REFERENCE_GLINT_P_SAMPLES, rotLight, rotBrdf);
  float p = integral / ggxTotalNdf(glintIsotropicAlpha(s.alpha));
  vec3 h = normalize(wo + toLocal(s, lightCentreDirection(L, s.position)));
  return glintFactor(gBinomial, h, p, REMAINING_LOGNORMAL);
}
#endif

Radiance shadeLight(Surface s, LightData L) {
  uint lightIndex = gReferenceLightIndex++;
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;

  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    return Radiance(materialDiffuseCos(s, wi) * irradiance, materialSpecularCos(s, wo, wi) * irradiance);
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
        result.diffuse += materialDiffuseCos(s, wi) * radiance / pdfLight;
        if (!mirror) {
          float w = powerHeuristic(pdfLight, brdfSamplePdf(s, wo, wi));
          result.specular += extentSpecularCos(s, wo, wi) * radiance * (w / pdfLight);
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
        if (pdfBrdf > 0.0) result.specular += extentSpecularCos(s, wo, wi) * radiance * (powerHeuristic(pdfBrdf, pdfL) / pdfBrdf);
      }
    }
  }
  result.diffuse /= float(n);
  result.specular /= float(n);
#if MATERIAL_BINOMIAL_GLINTS && !REFERENCE_BINOMIAL_REALISATION
  result.specular *= glintReferenceFactor(s, L, wo, uint(sub.y * k + sub.x), rotLight, rotBrdf);
#endif
  if (mirror) {
    float dist;
    vec3 r = reflect(-s.view, s.normal);
    if (lightHit(L, s.position, r, dist)) result.specular = fresnelSchlick(s.f0, wo.z) * radiance;
  }
  return result;
}
