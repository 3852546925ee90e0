// Shading with the glinty BRDF (Chermain et al. 2020, 2021), shared by the `chermain2020` and
// `chermain2021` modules and the reference: the per-pixel glint state (footprint, transformed
// lobe, optionally widened by LEAN mapping) and the BRDF f_P cos = F G D_P / (4 cos_o) with
// V-cavity masking-shadowing (2020, sec. 4.4). Materials without glints keep the lobe shading
// of `conventional`.
#include "common/brdf.glsl"
#include "common/glint_ndf.glsl"
#include "common/lights.glsl"
#include "common/lobe_shading.glsl"
#include "common/slope_moments.glsl"
#include "common/surface.glsl"

struct GlintSurface {
  GlintFootprint footprint;
  GlintLobe lobe;
  float logDensity;
  float relativeArea;
};

// The glint state of a surface whose material holds `glints` (MaterialData.glints): uv and
// footprint in the material's own uv (the normal-map tiling removed), the lobe of deviations
// alpha / sqrt(2) and the surface's correlation (set rho to 0 for the 2020 model).
GlintSurface glintSurface(Surface s, vec4 glints, float tiling, float rho) {
  GlintFootprint fp = glintFootprint(s.uv / tiling, s.dUVdx / tiling, s.dUVdy / tiling, glints.z);
  return GlintSurface(fp, glintLobe(s.alpha * 0.70710678, rho), glints.x, glints.y);
}

// LEAN mapping + glints (2021, sec. 5): the normal map's slope covariance inside the footprint
// added to the material's, Sigma = Sigma_m + Sigma_n, the shading normal moved to the mean slope.
// Sets s.alpha and s.rho to the combined lobe (so the smooth limit agrees with it).
void combineWithNormalMapSlopes(inout Surface s) {
#if MATERIAL_NORMAL_MAP
  vec2 meanSlope;
  mat2 normals = footprintSlopeCovariance(s, meanSlope);
  setShadingNormal(s, mappedNormal(vec3(meanSlope, 1.0), s.vertexTangent, s.vertexBitangent, s.vertexNormal));
  vec2 sigma = s.alpha * 0.70710678;
  mat2 total = mat2(sigma.x * sigma.x, s.rho * sigma.x * sigma.y, s.rho * sigma.x * sigma.y, sigma.y * sigma.y) + normals;
  vec2 combined = min(sqrt(vec2(total[0][0], total[1][1])), vec2(1.0));
  s.rho = clamp(total[0][1] / (combined.x * combined.y), -0.99, 0.99);
  s.alpha = combined * 1.41421356;
#endif
}

// The per-pixel step of the glint methods: LEAN + glints when asked, then the glint state of
// material m, with the surface's correlation (2021) or without (2020).
GlintSurface prepareGlints(inout Surface s, MaterialData m, bool lean, bool correlated) {
  if (lean) combineWithNormalMapSlopes(s);
  return glintSurface(s, m.glints, m.diffuse_tiling.a, correlated ? s.rho : 0.0);
}

// V-cavity masking (2020, eq. 8, after Cook & Torrance 1982) of direction w for microfacet h.
float vCavityG1(vec3 w, vec3 h) { return min(1.0, 2.0 * h.z * w.z / max(dot(w, h), 1e-9)); }

// f_P(wo, wi) cos(theta_i) of the glinty BRDF for local directions; `kernel` holds the filter's
// slope-space derivatives (used when filtered).
vec3 glintSpecularCos(GlintSurface g, vec3 wo, vec3 wi, vec3 f0, vec2 kernelDx, vec2 kernelDy, bool filtered) {
  vec3 h = normalize(wo + wi);
  if (wo.z <= 0.0 || wi.z <= 0.0 || h.z <= 0.0 || dot(wo, h) <= 0.0 || dot(wi, h) <= 0.0) return vec3(0.0);
  GlintQuery q = GlintQuery(-h.xy / h.z, kernelDx, kernelDy, filtered, g.logDensity, g.relativeArea);
  float cos2 = h.z * h.z;
  float d = glintP22(q, g.lobe, g.footprint) / (cos2 * cos2);
  float masking = vCavityG1(wo, h) * vCavityG1(wi, h);
  return fresnelSchlick(f0, dot(wo, h)) * (d * masking / (4.0 * wo.z));
}

// Where a light shines from, and the irradiance it gives at normal incidence: exact for delta
// lights; lights with extent as a point at their centre carrying radiance x solid angle (the
// glinty BRDFs of 2020/2021 are defined for point and directional lights only).
void glintLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  int type = lightType(L);
  if (type == LIGHT_POINT) {
    vec3 d = L.position_radius.xyz - p;
    float d2 = max(dot(d, d), 1e-12);
    l = d * inversesqrt(d2);
    irradiance = L.colour_type.rgb / d2;
  } else if (type == LIGHT_DIRECTIONAL) {
    l = -L.direction_cos.xyz;
    irradiance = L.colour_type.rgb;
  } else {
    l = lightCentreDirection(L, p);
    irradiance = lightRadiance(L) * lightSolidAngle(L, p, l);
  }
}

// Diffuse and glinty specular radiance from light direction l with the given irradiance.
Radiance shadeGlints(Surface s, GlintSurface g, vec3 l, vec3 irradiance, vec2 kernelDx, vec2 kernelDy, bool filtered) {
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance,
                  glintSpecularCos(g, wo, wi, s.f0, kernelDx, kernelDy, filtered) * irradiance);
}
