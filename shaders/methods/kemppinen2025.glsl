// Method `kemppinen2025`: Kemppinen et al. 2025's glinty NDF in constant time (glints/point-process/)
// with the pixel's footprint. Its material is the point-process-glints kind
// (MATERIAL_KIND_POINT_PROCESS_GLINTS); lights with extent are points at their centre (the paper's
// shader shades point lights); every other material is shaded as by `conventional`. Descriptor:
// src/shading/methods/kemppinen2025.cpp; docs/methods.md#kemppinen2025.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#include "glints/point-process/shading.glsl"
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_POINT_PROCESS_GLINTS
PointProcessFootprint gPointProcess;
#endif

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_POINT_PROCESS_GLINTS
  gPointProcess = preparePointProcessGlints(s, materials[uMaterial], param_footprint_scale);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_POINT_PROCESS_GLINTS
  vec3 l, irradiance;
  centreLightIncidence(L, s.position, l, irradiance);
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance, pointProcessSpecularCos(gPointProcess, wo, wi, s.f0) * irradiance);
#else
  return shadeLobe(s, L, materialSmoothLobe(s), AREA_LIGHTS_LTC);  // conventional's default
#endif
}
