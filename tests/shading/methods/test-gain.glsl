// Method `test-gain` (tests only): conventional's radiance times param_gain (the specular only
// when param_terms is TERMS_SPECULAR), declared in tests/shading/methods/test-gain.cpp.
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) {
  Radiance r = shadeLobe(s, L, materialLobe(s));
  float diffuseGain = param_terms == TERMS_SPECULAR ? 1.0 : param_gain;
  return Radiance(r.diffuse * diffuseGain, r.specular * param_gain);
}
