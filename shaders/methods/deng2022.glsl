// Method `deng2022`: Deng et al. 2022's constant-cost spatio-angular prefiltering, queried in real
// time: the pixel footprint's NDF read from the material's CP-compressed pyramid of NDF images
// (common/prefiltered_ndf.glsl) instead of summed over the map's elements as `yan2016` does.
// Delta lights: a point query at the half vector; lights with extent: a box query over the
// light's half-vector box. Cost independent of the footprint and of the light's size. Other
// materials are shaded as by `conventional` (lights with extent by LTC).
// Descriptor: src/shading/methods/deng2022.cpp; docs/methods.md#deng2022.
#include "common/lobe.glsl"
#include "common/lobe_shading.glsl"

#if MATERIAL_NORMAL_GLINTS
#include "common/position_normal.glsl"
#include "common/prefiltered_ndf.glsl"

vec2 gFootprintCentre;  // texels of the map
float gFootprintSigma;  // texels: the isotropic footprint of the same area
float gMaskingAlpha;
vec3 gDiffuseNormal;  // the map's filtered normal in the macro frame, for Lambert

float normalGlintsDensity(vec2 s) { return pndfDensity(uMaterial, gFootprintCentre, gFootprintSigma, s); }
float normalGlintsBoxMean(vec2 lo, vec2 hi) {
  return pndfRangeMean(uMaterial, gFootprintCentre, gFootprintSigma, lo, hi);
}
#include "common/normal_glints_shading.glsl"
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_NORMAL_GLINTS
  gDiffuseNormal = normalize(s.mappedNormal);
  s.anisotropyRotation = 0.0;
  setShadingNormal(s, s.vertexNormal);
  ivec2 size = textureSize(uNormalMap, 0);
  mat2 sigmaP = pixelFootprintCovariance(s.dUVdx, s.dUVdy, size, param_footprint_sigma);
  // The pyramid holds isotropic footprints: the one of the same area, sigma^2 = sqrt(det Sigma_p).
  gFootprintSigma = sqrt(sqrt(max(determinant(sigmaP), 0.0)));
  gFootprintCentre = fract(s.uv) * vec2(size);
  gMaskingAlpha = materials[uMaterial].glints.y;
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_NORMAL_GLINTS
  return shadeNormalGlints(s, L, gMaskingAlpha, gDiffuseNormal);
#else
  return shadeLobe(s, L, materialLobe(s), float(AREA_LIGHTS_LTC));  // conventional's default
#endif
}
