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
  mat2 covariance = sigma * sigma * f.uvCovariance;
  // Non-finite derivatives (at the horizon) give a point: the NDF's own floor of a facet spacing.
  if (any(isnan(vec4(covariance[0], covariance[1]))) || any(isinf(vec4(covariance[0], covariance[1]))))
    covariance = mat2(0.0);
  return pointProcessFootprint(s.uv / tiling, covariance, pointProcessGlintsLogDensity(m),
                               pointProcessGlintsMicrofacetRoughness(m), s.ndf, s.alpha);
}

// f cos for local directions.
vec3 pointProcessSpecularCos(PointProcessFootprint f, vec3 wo, vec3 wi, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * pointProcessNdf(f, h) * smithG2OverCos(f.kind, wo, wi, f.alpha));
}

// The solid-angle density of wi = reflect(-wo, h) for h from pointProcessSampleNormal.
float pointProcessReflectionPdf(PointProcessFootprint f, vec3 wo, vec3 wi) {
  vec3 h;
  float jacobian = reflectionJacobian(wo, wi, h);
  return jacobian > 0.0 ? pointProcessNormalPdf(f, h) * jacobian : 0.0;
}
