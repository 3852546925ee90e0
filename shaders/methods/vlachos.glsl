// Method `vlachos`: roughness clamped from below by the screen-space change of the vertex normal
// (Vlachos 2015). Descriptor: src/shading/methods/vlachos.cpp; docs/methods.md#vlachos.
#define METHOD_SHADES_ENVIRONMENT  // through shadeLobe, at its own lobe
#define METHOD_LOBES_KEEP_ISOTROPY  // the material's alpha widened alike along both axes (lobe/lobe_shading.glsl)
#include "lobe/lobe_shading.glsl"
#include "lobe/roughness_filtering.glsl"

void prepareSurface(inout Surface s) { s.alpha = vlachosAlpha(s.alpha, s.footprint.dNdx, s.footprint.dNdy, param_scale, param_exponent); }

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, materialSmoothLobe(s), param_area_lights); }
