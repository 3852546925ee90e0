// The sum of a shading module's shadeLight over every light of the scene, specialised on the
// scene's lights. The light buffer is sorted by kind (src/render/gpu_scene.cpp) and the program
// variant defines LIGHT_RANGES, the constant initialiser of each kind's index range [x, y), and
// LIGHT_<ID>_COUNT. shadeAllLights (generated from the kinds' registry) calls one loop per kind the
// scene has, with the kind's code as a constant: every loop has a constant trip count and a
// constant kind, so the compiler unrolls short loops, folds the dispatch of lights/lights.glsl to
// the kind's functions and loads each light from a constant offset, and the kinds the scene lacks
// are not compiled at all (generated/light_kinds.glsl). This matters on SIMD CPU drivers: Mesa's
// llvmpipe runs both sides of every branch and each loop iteration is costly, so an unspecialised
// loop costs the code of every kind for every light (measured in docs/results.md, "Speed").
#include "lights/lights.glsl"
#include "core/surface.glsl"
#include "lobe/environment_shading.glsl"

const ivec2 kLightRange[LIGHT_KIND_COUNT] = LIGHT_RANGES;

void addRadiance(inout Radiance sum, Radiance r) {
  sum.diffuse += r.diffuse;
  sum.specular += r.specular;
}

// A light that is not compact (an environment): a module that shades it itself says so with
// `#define METHOD_SHADES_ENVIRONMENT` (the lobe methods, with their own lobe; the reference); any
// other shades it as its material's smooth limit by the split sum (the glint methods and podee for
// now: docs/methods.md, "Environment lights").
Radiance shadeEnvironmentLight(Surface s, LightData L) {
#ifdef METHOD_SHADES_ENVIRONMENT
  return shadeLight(s, L);
#else
  return shadeLobeEnvironment(s, L, materialSmoothLobe(s));
#endif
}

// The lights of a compact kind.
Radiance shadeCompactLights(Surface s, const int kind) {
  Radiance sum = Radiance(vec3(0.0), vec3(0.0));
  for (int i = kLightRange[kind].x; i < kLightRange[kind].y; ++i) {
    LightData L = lights[i];
    L.colour_type.a = float(kind);  // a constant: lightType(L) folds to this kind
    addRadiance(sum, shadeLight(s, L));
  }
  return sum;
}

// The lights of a kind that is not compact.
Radiance shadeEnvironmentLights(Surface s, const int kind) {
  Radiance sum = Radiance(vec3(0.0), vec3(0.0));
  for (int i = kLightRange[kind].x; i < kLightRange[kind].y; ++i) {
    LightData L = lights[i];
    L.colour_type.a = float(kind);
    addRadiance(sum, shadeEnvironmentLight(s, L));
  }
  return sum;
}

#include "generated/shade_all_lights.glsl"
