// The normal-map-glints material's microsurface at one point u (Yan et al. 2016's model; the
// contract in docs/scene-format.md#normal-map-glints-materials): the map's normal n(u) (bilinear at
// level 0, renormalised) and, about it, a Gaussian of the projected normal s = h.xy,
//   P(s | u) = N2(s; n(u).xy, sigma_r^2 I),
// in the MACRO tangent frame (the interpolated vertex frame, never the mapped normal's). P is a
// density over the unit disk of projected normals, ds = h.z dw_h, so the NDF normalised as
// integral D(h) h.z dw_h = 1 is D(h) = P(h.xy | u) itself. What the reference evaluates; no filtering.
#include "core/brdf.glsl"
#include "core/constants.glsl"
#include "core/material.glsl"
#include "core/sampling.glsl"
#include "generated/gpu_contract.glsl"

struct NormalGlintPoint {
  vec3 normal;         // n(u) in the macro frame (unit)
  float sigma;         // sigma_r, the intrinsic roughness
  float maskingAlpha;  // Beckmann alpha of the whole microsurface, for Smith G2 only
};

// `mapped`: the normal map's texel at u (bilinear, level 0; not renormalised); `m`: the material.
NormalGlintPoint normalGlintPoint(vec3 mapped, MaterialData m) {
  return NormalGlintPoint(normalize(mapped), normalMapGlintsIntrinsicRoughness(m), normalMapGlintsMaskingAlpha(m));
}

// P(s | u): the isotropic 2D Gaussian of the projected normal.
float normalGlintDensity(NormalGlintPoint p, vec2 s) {
  vec2 d = s - p.normal.xy;
  float invVar = 1.0 / (p.sigma * p.sigma);
  return (0.5 * INV_PI) * invVar * exp(-0.5 * dot(d, d) * invVar);
}

// D(h) = P(h.xy | u) for h above the macro surface.
float normalGlintNdf(NormalGlintPoint p, vec3 h) { return h.z > 0.0 ? normalGlintDensity(p, h.xy) : 0.0; }

// f(wo, wi) wi.z = F(wo.h) G2(wo, wi; masking alpha) D(h) / (4 wo.z), macro-frame directions.
vec3 normalGlintSpecularCos(NormalGlintPoint p, vec3 wo, vec3 wi, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float g2OverCos = smithG2OverCos(NDF_BECKMANN, wo, wi, vec2(p.maskingAlpha));
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * normalGlintNdf(p, h) * g2OverCos);
}

// A normal h whose projection s = h.xy is drawn from P(. | u) (Box-Muller on u); vec3(0) when s
// falls outside the unit disk, where no normal lies: reflect(-wo, 0) = -wo is below the horizon,
// so the caller drops the sample, and the density below is that of the samples kept.
vec3 sampleNormalGlintNormal(NormalGlintPoint p, vec2 u) {
  float r = p.sigma * sqrt(-2.0 * log(max(1.0 - u.x, 1e-12)));
  float phi = TWO_PI * u.y;
  vec2 s = p.normal.xy + r * vec2(cos(phi), sin(phi));
  float s2 = dot(s, s);
  return s2 < 1.0 ? vec3(s, sqrt(1.0 - s2)) : vec3(0.0);
}

// Solid-angle density of wi = reflect(-wo, h) for h from sampleNormalGlintNormal: the density of h
// is P(h.xy) ds/dw_h = D(h) h.z, times the reflection Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
float normalGlintReflectionPdf(NormalGlintPoint p, vec3 wo, vec3 wi) {
  vec3 h;
  float jacobian = reflectionJacobian(wo, wi, h);
  return jacobian > 0.0 ? normalGlintNdf(p, h) * h.z * jacobian : 0.0;
}
