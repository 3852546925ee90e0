// Shading of a `normal-map-glints` material (Yan et al. 2016's model; docs/methods.md#yan2016) by a
// method that knows the pixel footprint's P-NDF P(s) over the projected half vector s = h.xy, in
// the macro (tangent) frame: f = F(v.h) G2(v, l) D(h) / (4 v.z l.z) with D(h) = P(h.xy) (P is a
// density over s, ds = h.z dw_h, so D = P is the NDF normalised as integral D h.z dw_h = 1, as the
// reference's glints/normal-map/surface.glsl), and G2 the height-correlated Smith masking of a
// Beckmann surface of the material's masking_alpha.
// The methods differ only in how they query P. Before including, define
//   float normalGlintsDensity(vec2 s);            // P at s
//   float normalGlintsBoxMean(vec2 lo, vec2 hi);  // the mean of P over the box [lo, hi]
// Delta lights: L_o = E F G2 P(h.xy) / (4 v.z) (E: irradiance at normal incidence).
// Lights with extent: P averaged over the light's half-vector box (glints/normal-map/light_half_vector_box.glsl)
// and everything else at its centre: L_o = L_e Omega F(v.h_c) G2(v, l_c) mean_P / (4 v.z). (Over the
// light, dw_l = 4 (v.h) dw_h = 4 (v.h) ds / h.z and the box has the area Omega h.z / (4 v.h) of the
// light's image in s, so the integral of D over the light is mean_P Omega.)
// Lambert diffuse about the map's (filtered) normal, the light as a point at its centre.
#include "core/brdf.glsl"
#include "glints/normal-map/light_half_vector_box.glsl"
#include "lights/lights.glsl"
#include "core/surface.glsl"

// Puts the surface back into its macro (vertex) frame, where the model's P lives (over the
// projected normals of the map's own tangent frame), and returns the map's filtered normal, about
// which the diffuse part is Lambert (as in the reference).
vec3 normalGlintsMacroFrame(inout Surface s) {
  vec3 diffuseNormal = normalize(s.mappedNormal);
  s.anisotropyRotation = 0.0;
  setShadingNormal(s, s.vertexNormal);
  return diffuseNormal;
}

// F G2 P / (4 v.z): the specular term times l.z, per unit irradiance, for a given P at h.
vec3 normalGlintsSpecularCos(vec3 wo, vec3 wi, vec3 h, float P, vec3 f0, float maskingAlpha) {
  if (wo.z <= 0.0 || wi.z <= 0.0 || h.z <= 0.0) return vec3(0.0);
  float g2OverCos = smithG2OverCos(NDF_BECKMANN, wo, wi, vec2(maskingAlpha));
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * P * g2OverCos);
}

// Lambert about the unit local normal n, times the cosine.
vec3 normalGlintsDiffuseCos(vec3 albedo, vec3 n, vec3 wi) { return albedo * (INV_PI * max(dot(n, wi), 0.0)); }

// One light; `s` in the macro frame (s.normal = the vertex normal); diffuseNormal: the map's
// normal in that frame (local, unit).
Radiance shadeNormalGlints(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    result.diffuse = normalGlintsDiffuseCos(s.diffuse, diffuseNormal, wi) * irradiance;
    if (wi.z <= 0.0) return result;
    vec3 h = normalize(wo + wi);
    result.specular = normalGlintsSpecularCos(wo, wi, h, normalGlintsDensity(h.xy), s.f0, maskingAlpha) * irradiance;
    return result;
  }
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (solidAngle <= 0.0) return result;
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));  // of the cone of equal (projected) solid angle
  vec3 radiance = lightRadiance(L) * solidAngle;
  vec3 lc = toLocal(s, centreDir);
  result.diffuse = normalGlintsDiffuseCos(s.diffuse, diffuseNormal, lc) * radiance;
  if (lc.z <= 0.0) return result;
  vec3 dl1, dl2;
  lightOutline(L, s.position, centreDir, sinHalf, dl1, dl2);
  HalfVectorBox box = halfVectorBox(wo, lc, toLocal(s, dl1), toLocal(s, dl2));
  float meanP = normalGlintsBoxMean(box.centre - box.halfExtent, box.centre + box.halfExtent);
  result.specular = normalGlintsSpecularCos(wo, lc, box.h, meanP, s.f0, maskingAlpha) * radiance;
  return result;
}
