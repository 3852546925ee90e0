// Shading with the glinty BRDF (Chermain et al. 2020, 2021), shared by the `chermain2020` and
// `chermain2021` modules and the reference: the per-pixel glint state (footprint, transformed
// lobe, optionally widened by LEAN mapping) and the BRDF f_P cos = F G D_P / (4 cos_o) with
// V-cavity masking-shadowing (2020, sec. 4.4). Materials without glints keep the lobe shading
// of `conventional`.
#include "core/brdf.glsl"
#include "glints/chermain/ndf.glsl"
#include "lights/lights.glsl"
#include "lobe/lobe_shading.glsl"
#include "lobe/slope_moments.glsl"
#include "core/surface.glsl"

struct GlintSurface {
  GlintPatch footprint;
  GlintLobe lobe;
  float logDensity;
  float relativeArea;
};

// The per-pixel step of the glint methods and the reference, for a surface of glinty material m:
// the footprint in the material's own uv (the normal-map tiling removed), and the lobe: the
// material's (A = 2 Sigma, rho included), widened by LEAN + glints when asked (2021, sec. 5:
// Sigma_m + Sigma_n about the mean normal), without its correlation for the 2020 model.
GlintSurface prepareGlints(inout Surface s, MaterialData m, bool lean, bool correlated) {
  Lobe lobe = materialLobe(s);
#if MATERIAL_NORMAL_MAP
  if (lean) lobe.A += 2.0 * leanShadingFrame(s);
#endif
  if (!correlated) lobe.A[0][1] = lobe.A[1][0] = 0.0;
  float tiling = m.diffuse_tiling.a;
  return GlintSurface(glintPatch(s.uv / tiling, footprintInUnits(s.footprint, tiling), glintyMaxAnisotropy(m)),
                      glintLobe(lobe.A), glintyLogDensity(m), glintyRelativeArea(m));
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

// Diffuse and glinty specular radiance from light direction l with the given irradiance.
Radiance shadeGlints(Surface s, GlintSurface g, vec3 l, vec3 irradiance, vec2 kernelDx, vec2 kernelDy, bool filtered) {
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance,
                  glintSpecularCos(g, wo, wi, s.f0, kernelDx, kernelDy, filtered) * irradiance);
}
