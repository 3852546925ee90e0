// Shading with the point-process glinty NDF (glints/point-process/ndf.glsl): a surface point's
// footprint from its pixel footprint, and the glinty BRDF (the NDF with height-correlated Smith
// masking-shadowing of the base NDF and Schlick Fresnel, as for every microfacet lobe here).
#include "core/brdf.glsl"
#include "core/surface.glsl"
#include "glints/point-process/ndf.glsl"

// The footprint of s in the material's own uv (its normal-map tiling undone): the pixel filter's
// Gaussian (PIXEL_FILTER_SIGMA pixels) mapped by the uv Jacobian, scaled by `footprintScale`.
PointProcessFootprint preparePointProcessGlints(Surface s, MaterialData m, float footprintScale) {
  float tiling = m.diffuse_tiling.a;
  Footprint f = footprintInUnits(s.footprint, tiling);
  float sigma = PIXEL_FILTER_SIGMA * footprintScale;
  return pointProcessFootprint(s.uv / tiling, sigma * sigma * f.uvCovariance, pointProcessGlintsLogDensity(m),
                               pointProcessGlintsMicrofacetRoughness(m), s.ndf, s.alpha);
}

// f cos for local directions.
vec3 pointProcessSpecularCos(PointProcessFootprint f, vec3 wo, vec3 wi, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * pointProcessNdf(f, h) * smithG2OverCos(f.kind, wo, wi, f.alpha));
}

// The solid-angle density of wi = reflect(-wo, h) for h from pointProcessSampleNormal: the density of
// h times the reflection Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
float pointProcessReflectionPdf(PointProcessFootprint f, vec3 wo, vec3 wi) {
  vec3 m = wo + wi;
  if (dot(m, m) <= 0.0) return 0.0;
  vec3 h = normalize(m);
  float oh = dot(wo, h);
  if (oh <= 0.0) return 0.0;
  return pointProcessNormalPdf(f, h) / (4.0 * oh);
}
