// Method `test-gain` (tests only): conventional's radiance times param_gain, declared in
// tests/shading/methods/test-gain.cpp.
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  Radiance r = shadeLobe(s, L, materialLobe(s));
  return Radiance(r.diffuse * param_gain, r.specular * param_gain);
}
