// Method `conventional`: the BRDF evaluated once at the pixel centre (the baseline to beat).
// Descriptor: src/shading/methods/conventional.cpp; docs/methods.md#conventional.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, materialSmoothLobe(s), param_area_lights); }
