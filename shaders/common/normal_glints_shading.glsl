// Shading of a `normal-map-glints` material (Yan et al. 2016's model; docs/methods.md#yan2016) by a
// method that knows the pixel footprint's P-NDF P(s) over the projected half vector s = h.xy, in
// the macro (tangent) frame: f = F(v.h) G2(v, l) D(h) / (4 v.z l.z) with D(h) = P(h.xy) / h.z, and
// G2 the height-correlated Smith masking of a Beckmann surface of the material's masking_alpha.
// The methods differ only in how they query P. Before including, define
//   float normalGlintsDensity(vec2 s);            // P at s
//   float normalGlintsBoxMean(vec2 lo, vec2 hi);  // the mean of P over the box [lo, hi]
// Delta lights: L_o = E F G2 P(h.xy) / (4 v.z h.z) (E: irradiance at normal incidence).
// Lights with extent: P averaged over the light's half-vector box (common/light_half_vector_box.glsl)
// and everything else at its centre: L_o = L_e Omega F(v.h_c) G2(v, l_c) mean_P / (4 v.z h_c.z).
// Lambert diffuse about the macro normal, the light as a point at its centre.
#include "common/brdf.glsl"
#include "common/light_half_vector_box.glsl"
#include "common/lights.glsl"
#include "common/surface.glsl"

// F G2 P / (4 v.z h.z): the specular term times l.z, per unit irradiance, for a given P at h.
vec3 normalGlintsSpecularCos(vec3 wo, vec3 wi, vec3 h, float P, vec3 f0, float maskingAlpha) {
  if (wo.z <= 0.0 || wi.z <= 0.0 || h.z <= 0.0) return vec3(0.0);
  float g2OverCos = smithG2OverCos(NDF_BECKMANN, wo, wi, vec2(maskingAlpha));
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * P * g2OverCos / h.z);
}

// One light; `s` in the macro frame (s.normal = the vertex normal).
Radiance shadeNormalGlints(Surface s, LightData L, float maskingAlpha) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    if (wi.z <= 0.0) return result;
    vec3 h = normalize(wo + wi);
    result.diffuse = diffuseCos(s.diffuse, wi) * irradiance;
    result.specular = normalGlintsSpecularCos(wo, wi, h, normalGlintsDensity(h.xy), s.f0, maskingAlpha) * irradiance;
    return result;
  }
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (solidAngle <= 0.0) return result;
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));  // of the cone of equal (projected) solid angle
  vec3 radiance = lightRadiance(L) * solidAngle;
  vec3 lc = toLocal(s, centreDir);
  result.diffuse = diffuseCos(s.diffuse, lc) * radiance;
  if (lc.z <= 0.0) return result;
  vec3 dl1, dl2;
  lightOutline(L, s.position, centreDir, sinHalf, dl1, dl2);
  HalfVectorBox box = halfVectorBox(wo, lc, toLocal(s, dl1), toLocal(s, dl2));
  float meanP = normalGlintsBoxMean(box.centre - box.halfExtent, box.centre + box.halfExtent);
  result.specular = normalGlintsSpecularCos(wo, lc, box.h, meanP, s.f0, maskingAlpha) * radiance;
  return result;
}
