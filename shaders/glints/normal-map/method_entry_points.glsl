// The method interface (prepareSurface, shadeLight) of a method that renders normal-map-glints
// materials by their footprint's NDF (yan2016, deng2022): the footprint at each pixel and every
// light by glints/normal-map/environment_lobes.glsl's shadeNormalGlintsLight; other materials as
// `conventional` shades them. Compiled as a footprint NDF for the path tracer
// (METHOD_AS_FOOTPRINT_NDF) the method has no entry points: the path tracer's material calls it.
// Needs the method's normalGlintsPrepareFootprint, gMaskingAlpha and gDiffuseNormal.
#ifndef METHOD_AS_FOOTPRINT_NDF
void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
  normalGlintsPrepareFootprint(s);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
  return shadeNormalGlintsLight(s, L, gMaskingAlpha, gDiffuseNormal);
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
#endif  // METHOD_AS_FOOTPRINT_NDF
