// Method `deng2022`: Deng et al. 2022's constant-cost spatio-angular prefiltering, queried in real
// time: the pixel footprint's NDF read from the material's CP-compressed pyramid of NDF images
// (glints/normal-map/prefiltered_ndf.glsl) instead of summed over the map's elements as `yan2016` does.
// Delta lights: a point query at the half vector; lights with extent: a box query over the
// light's half-vector box. Cost independent of the footprint and of the light's size; footprints
// finer than the pyramid's first level are summed over the map's elements as yan2016 does (the
// paper's switch, sec. 5.1), at a cost bounded by that level's size. Other
// materials are shaded as by `conventional` (lights with extent by LTC).
// Descriptor: src/shading/methods/deng2022.cpp; docs/methods.md#deng2022.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
#include "glints/normal-map/position_normal.glsl"
#include "glints/normal-map/prefiltered_ndf.glsl"

vec2 gFootprintCentre;  // texels of the map
float gFootprintSigma;  // texels: the isotropic footprint of the same area
float gMaskingAlpha;
vec3 gDiffuseNormal;  // the map's filtered normal in the macro frame, for Lambert
// Footprints finer than the pyramid's first level: Yan 2016's sum over the elements (k = 1), as
// the paper does (sec. 5.1); its loop is empty (count 0) where the pyramid answers.
bool gBelowPyramid;
PositionNormalFootprint gElements;

float normalGlintsDensity(vec2 s) {
  return gBelowPyramid ? positionNormalDensity(uNormalMap, gElements, 1, s)
                       : pndfDensity(uMaterial, gFootprintCentre, gFootprintSigma, s);
}
float normalGlintsBoxMean(vec2 lo, vec2 hi) {
  return gBelowPyramid ? positionNormalBoxMean(uNormalMap, gElements, 1, lo, hi)
                       : pndfRangeMean(uMaterial, gFootprintCentre, gFootprintSigma, lo, hi);
}
#include "glints/normal-map/shading.glsl"
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
  gDiffuseNormal = normalGlintsMacroFrame(s);
  ivec2 size = textureSize(uNormalMap, 0);
  mat2 sigmaP = footprintTexelCovariance(s.footprint, size, param_footprint_sigma);
  // The pyramid holds isotropic footprints: the one of the same area, sigma^2 = sqrt(det Sigma_p).
  gFootprintSigma = sqrt(sqrt(max(determinant(sigmaP), 0.0)));
  gFootprintCentre = fract(s.uv) * vec2(size);
  MaterialData m = materials[uMaterial];
  gMaskingAlpha = normalMapGlintsMaskingAlpha(m);
  // Below sigma_0 the elements within 3 sigma_0 (plus the element's own extent) are all a footprint
  // can reach: a bounded loop, (6 sigma_0 + 3)^2 elements at most, within llvmpipe's loop budget.
  float sigma0 = pndfFirstSigma(uMaterial);
  gBelowPyramid = param_small_footprints == SMALL_FOOTPRINTS_YAN2016 && gFootprintSigma < sigma0;
  gElements = positionNormalFootprint(gFootprintCentre, sigmaP, size, 1, normalMapGlintsIntrinsicRoughness(m),
                                       positionNormalRadiusBudget(3.0 * sigma0 + 1.5, 1));
  if (!gBelowPyramid) gElements.count = ivec2(0);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
  return shadeNormalGlints(s, L, gMaskingAlpha, gDiffuseNormal);
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
