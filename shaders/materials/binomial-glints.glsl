// Material kind `binomial-glints` (src/scene/materials/binomial_glints.cpp): Deliot & Belcour's
// binomial glints (glints/binomial/) with the shading point's own footprint, cells one sub-pixel
// across. Under lights with extent it is Kneiphof & Klein 2024's model without its approximations
// (docs/methods.md#kneiphof2024, "Two references"): the smooth GGX integrated over the light,
// times the glint factor of the probability p that a facet reflects the light, p integrated
// numerically. With REFERENCE_SURFACE_REALISATION (the raster-realisation backend) it is one
// fixed realisation of the microfacets instead (glints/binomial/realisation.glsl), and with
// REFERENCE_SURFACE_FACETS (the raster-facets backend) a fixed field of mirror facets, one per uv
// cell, that shares nothing with the counting model (glints/binomial/facets.glsl). Sampled as its
// smooth limit, the GGX lobe of alpha (a facet: its own lobe).
#include "core/brdf.glsl"
#include "core/sampling.glsl"
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/light_ndf_integral.glsl"
#include "lights/light_data.glsl"
#include "lobe/lobe.glsl"
// The references' surfaces, included unconditionally: the shader library expands includes before
// the preprocessor runs, so a file first included inside a false #if would hide its own includes
// from every later file (functions no program calls cost nothing).
#include "glints/binomial/realisation.glsl"
#include "glints/binomial/facets.glsl"
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
BinomialFacet gBinomialFacet;  // the facet this sample lands on
#endif

BinomialSurface gBinomialGlintsMaterial;  // the binomial glints with this point's own footprint
// Cells one sub-pixel across (Shannon's limit at the sub-pixel scale; the pixel averages them).
const float BINOMIAL_MATERIAL_SCREEN_SPACE_SCALE = 1.0;
// Samples of each strategy for the probability that a facet reflects a light with extent: p's own
// error, against quadrature over the light, is 0.5% relative on average and 7% at most wherever
// p >= 1e-4 (tests/glsl/test_glint_light_probability.cpp), far below the LTC's and the cap's.
const uint BINOMIAL_MATERIAL_P_SAMPLES = 128u;

void binomialGlintsMaterialPrepare(inout Surface s, MaterialData m) {
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
  gBinomialFacet = binomialFacetAt(s.uv / m.diffuse_tiling.a, binomialGlintsLogDensity(m), s.alpha,
                                   binomialGlintsMicrofacetRoughness(m));
#else
  gBinomialGlintsMaterial = prepareBinomialGlints(s, m, BINOMIAL_MATERIAL_SCREEN_SPACE_SCALE);
#endif
}

// Under delta lights (and, in a realisation, under every light): the glinty BRDF itself.
vec3 binomialGlintsMaterialSpecularCos(Surface s, vec3 wo, vec3 wi) {
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
  return binomialFacetDeltaSpecularCos(gBinomialFacet, wo, wi, s.f0, s.alpha);
#elif REFERENCE_SURFACE == REFERENCE_SURFACE_REALISATION
  return binomialRealisationSpecularCos(gBinomialGlintsMaterial, wo, wi, s.f0, s.alpha);
#else
  return binomialSpecularCos(gBinomialGlintsMaterial, wo, wi, s.f0, s.alpha, REMAINING_COUNT_LOGNORMAL);
#endif
}

vec3 binomialGlintsMaterialDiffuseCos(Surface s, vec3 wi) { return diffuseCos(s.diffuse, wi); }

vec3 binomialGlintsMaterialSampleNormal(Surface s, vec3 wo, vec2 u) {
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
  return binomialFacetSampleNormal(gBinomialFacet, u);
#else
  return s.ndf == NDF_BECKMANN ? sampleBeckmannNormal(s.alpha, u) : sampleGGXVisibleNormal(wo, s.alpha, u);
#endif
}

float binomialGlintsMaterialSamplePdf(Surface s, vec3 wo, vec3 wi) {
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
  return binomialFacetSamplePdf(gBinomialFacet, wo, wi);
#else
  return s.ndf == NDF_BECKMANN ? beckmannReflectionPdf(wo, wi, s.alpha) : ggxVisibleReflectionPdf(wo, wi, s.alpha);
#endif
}

Lobe binomialGlintsMaterialSmoothLobe(Surface s) { return materialLobe(s); }

// Lights with extent: the smooth GGX, whose integral the glint factor then scales.
vec3 binomialGlintsMaterialLightIntegrand(Surface s, vec3 wo, vec3 wi) {
#if REFERENCE_SURFACE == REFERENCE_SURFACE_FACETS
  return binomialFacetSpecularCos(gBinomialFacet, wo, wi, s.f0, s.alpha);
#elif REFERENCE_SURFACE == REFERENCE_SURFACE_REALISATION
  return binomialGlintsMaterialSpecularCos(s, wo, wi);
#else
  return specularCos(NDF_GGX, wo, wi, s.alpha, s.f0);
#endif
}

// The probability that a facet reflects the light, p = integral over the light of
// D(h) / (4 |l.h|) dl (above the horizon) / T, integrated numerically with
// BINOMIAL_MATERIAL_P_SAMPLES samples of each strategy (sub-pixel `sub` of k^2 takes its slice of
// the pixel's sequence), then the glint factor at the half vector towards the light's centre, as
// the method draws it.
float binomialGlintsMaterialLightFactor(Surface s, LightData L, vec3 wo, uint sub, vec2 rotLight, vec2 rotBrdf) {
#if REFERENCE_SURFACE != REFERENCE_SURFACE_MODEL
  return 1.0;
#else
  float integral = lightNdfIntegral(s, L, wo, sub * BINOMIAL_MATERIAL_P_SAMPLES, BINOMIAL_MATERIAL_P_SAMPLES,
                                    rotLight, rotBrdf);
  float p = integral / ggxTotalNdf(glintIsotropicAlpha(s.alpha));
  vec3 h = normalize(wo + toLocal(s, lightCentreDirection(L, s.position)));
  return glintFactor(gBinomialGlintsMaterial, h, p, REMAINING_COUNT_LOGNORMAL);
#endif
}
