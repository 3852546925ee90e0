// Shading with the binomial glints of Deliot & Belcour 2023 (docs/methods.md#deliot2023), shared
// by the `deliot2023` module and the reference: the per-pixel glint state of a binomial-glints
// material and the microfacet BRDF with D_glint in place of D: f cos = F G2 D_glint / (4 cos_o),
// the material's GGX with height-correlated Smith masking-shadowing (core/brdf.glsl).
#include "glints/binomial/ndf.glsl"
#include "core/brdf.glsl"
#include "lights/lights.glsl"
#include "core/material.glsl"
#include "core/surface.glsl"

// The per-pixel step: the footprint in the material's own uv (the normal-map tiling removed, as
// for Chermain's glints), cells screenSpaceScale pixels across.
BinomialSurface prepareBinomialGlints(Surface s, MaterialData m, float screenSpaceScale) {
  float tiling = m.diffuse_tiling.a;
  BinomialFootprint f = binomialFootprint(footprintInUnits(s.footprint, tiling), screenSpaceScale);
  return binomialSurface(s.uv / tiling, f, binomialGlintsLogDensity(m), binomialGlintsDensityRandomization(m),
                         binomialGlintsMicrofacetRoughness(m), binomialGlintsSlopeGridScale(m));
}

// f cos for local directions.
vec3 binomialSpecularCos(BinomialSurface b, vec3 wo, vec3 wi, vec3 f0, vec2 alpha, int model) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float d = binomialNdf(b, h, alpha, model);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * d * smithG2OverCos(NDF_GGX, wo, wi, alpha));
}

// Diffuse and glinty specular radiance from light direction l with the given irradiance.
Radiance shadeBinomialGlints(Surface s, BinomialSurface b, vec3 l, vec3 irradiance, int model) {
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance,
                  binomialSpecularCos(b, wo, wi, s.f0, s.alpha, model) * irradiance);
}
