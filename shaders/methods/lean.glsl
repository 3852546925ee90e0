// Method `lean`: LEAN mapping (Olano & Baker 2010): the normal map's slope moments, filtered by
// the texture hardware, give the mean normal and the slope covariance inside the pixel's
// texture footprint. Descriptor: src/shading/methods/lean.cpp; docs/methods.md#lean.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#if !MATERIAL_NORMAL_MAP  // without a map the lobe is the material's own (lobe/lobe_shading.glsl)
#define METHOD_LOBES_KEEP_ISOTROPY
#endif
#include "lobe/lobe_shading.glsl"
#include "lobe/slope_moments.glsl"

Lobe gLeanLobe;  // this pixel's lobe, set by prepareSurface

void prepareSurface(inout Surface s) {
  gLeanLobe = materialSmoothLobe(s);
#if MATERIAL_NORMAL_MAP
  gLeanLobe.A += 2.0 * leanShadingFrame(s);
#endif
}

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, gLeanLobe, param_area_lights); }
