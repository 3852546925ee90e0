// Method `kneiphof2024`: Kneiphof & Klein 2024, glints under area lights: the binomial counting of
// deliot2023 driven by the probability that a facet reflects the light (the D-only LTC, or the GGX
// LTC's integral with the D-only magnitude, for large lights; the small-cap NDF for small ones),
// the glint factor scaling the light's LTC integral; optionally the light cut into 2 x 2 or 4 x 4
// cells split hierarchically. Other materials are shaded as by `conventional`. Descriptor:
// src/shading/methods/kneiphof2024.cpp; docs/methods.md#kneiphof2024.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
const int LIGHT_CELLS = param_subdivision == SUBDIVISION_4X4 ? 16 : param_subdivision == SUBDIVISION_2X2 ? 4 : 1;
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/subdivision.glsl"
BinomialSurface gBinomial;
GlintLtc gLtc;  // the LTC terms of the pixel's lobe, shared by every light
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
  gBinomial = prepareBinomialGlints(s, materials[uMaterial], param_screen_space_scale);
  gLtc = glintLtc(s);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
  const int model = param_remaining_count;  // REMAINING_COUNT_*
  const bool reuseGgxShape = param_light_probability == LIGHT_PROBABILITY_GGX_LTC;
  if (!lightHasExtent(L)) return shadeBinomialDeltaGlints(s, gBinomial, L, param_point_light_solid_angle, model);
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (wo.z <= 0.0 || solidAngle <= 0.0) return result;
  vec3 radiance = lightRadiance(L);
  LtcLightForm form = ltcLightForm(s, L);  // shared by the diffuse and the specular integrals
  result.diffuse = s.diffuse * ltcLightFormFactor(form, L) * radiance;
  if (LIGHT_CELLS > 1 && lightHasPolygonForm(L)) {
    result.specular = subdividedGlintSpecular(s, gLtc, gBinomial, L, wo, model, reuseGgxShape) * radiance;
  } else {
    GlintLightIntegral g = glintLightIntegral(s, gLtc, L, form, wo, centreDir, solidAngle, reuseGgxShape);
    result.specular = glintFactor(gBinomial, g.hCentre, g.p, model) * g.specular * radiance;
  }
  return result;
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
