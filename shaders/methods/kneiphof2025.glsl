// Method `kneiphof2025`: Kneiphof & Klein 2025, glints under image-based lighting: the split-sum
// radiance of an environment scaled by the glints of the footprint's binomial facets split among
// the environment's luminance regions (glints/binomial/environment_glints.glsl); compact lights as
// kneiphof2024 (undivided). Other materials are shaded as by `conventional`. Descriptor:
// src/shading/methods/kneiphof2025.cpp; docs/methods.md#kneiphof2025.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#define METHOD_SHADES_ENVIRONMENT   // binomial glints by the regions; others as conventional
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
const int LIGHT_CELLS = 4;  // the environment's regions
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/environment_glints.glsl"
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
  if (!lightIsCompact(L)) {
    Lobe lobe = materialSmoothLobe(s);
    Radiance result = shadeLobeEnvironment(s, L, lobe);
    // p: the D-only LTC's magnitude over T, the share of facets reflecting into the hemisphere.
    result.specular *= environmentGlintFactor(s, gBinomial, L, lobeEquivalentAlpha(lobe), min(gLtc.ndfScale, 1.0), model);
    return result;
  }
  if (!lightHasExtent(L)) return shadeBinomialDeltaGlints(s, gBinomial, L, 0.0, model);
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (wo.z <= 0.0 || solidAngle <= 0.0) return result;
  vec3 radiance = lightRadiance(L);
  LtcLightForm form = ltcLightForm(s, L);
  result.diffuse = s.diffuse * ltcLightFormFactor(form, L) * radiance;
  GlintLightIntegral g = glintLightIntegral(s, gLtc, L, form, wo, centreDir, solidAngle, false);
  result.specular = glintFactor(gBinomial, g.hCentre, g.p, model) * g.specular * radiance;
  return result;
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
