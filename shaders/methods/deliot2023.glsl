// Method `deliot2023`: Deliot & Belcour 2023, glinty appearance by distributed binomial laws on
// anisotropic grids, with the fixes of Kneiphof & Klein's code (glints/binomial/*.glsl). Its
// material is the binomial-glints kind (MATERIAL_KIND_BINOMIAL_GLINTS); every other material is shaded
// as by `conventional`. Descriptor: src/shading/methods/deliot2023.cpp; docs/methods.md#deliot2023.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#include "glints/binomial/shading.glsl"
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
BinomialSurface gBinomial;
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
  gBinomial = prepareBinomialGlints(s, materials[uMaterial], param_screen_space_scale);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_BINOMIAL_GLINTS
  vec3 l, irradiance;
  centreLightIncidence(L, s.position, l, irradiance);
  return shadeBinomialGlints(s, gBinomial, l, irradiance, param_remaining_count);
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
