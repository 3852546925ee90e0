// The sum of a shading module's shadeLight over every light of the scene, specialised on the
// scene's lights. The light buffer is sorted by kind (src/render/gpu_scene.cpp) and the program
// variant defines LIGHT_RANGES, the constant initialiser of each kind's index range [x, y), and
// LIGHT_<ID>_COUNT. shadeAllLights (generated from the kinds' registry) calls one loop per kind the
// scene has, with the kind's code as a constant: the dispatch of lights/lights.glsl folds to the
// kind's functions, and the kinds the scene lacks are not compiled at all
// (generated/light_kinds.glsl). The trip count depends on the driver profile
// (core/driver_profile.glsl): a constant in the software profile, so the compiler unrolls short
// loops and loads each light from a constant offset (Mesa's llvmpipe runs both sides of every
// branch and each loop iteration is costly: an unspecialised loop costs the code of every kind for
// every light, docs/results.md, "Speed"); in the hardware profile the same count plus a zero the
// compiler cannot see, so each kind's loop stays rolled, one body in the instruction cache.
#include "core/driver_profile.glsl"
#include "core/frame.glsl"
#include "lights/lights.glsl"
#include "core/surface.glsl"
#include "lobe/environment_shading.glsl"

const ivec2 kLightRange[LIGHT_KIND_COUNT] = LIGHT_RANGES;

// The end of a kind's range as the profile's loops see it (frame.target.w is 0: the renderer's).
int lightRangeEnd(const int kind) {
#if PROFILE_ROLLED_LIGHT_LOOPS
  return kLightRange[kind].y + frame.target.w;
#else
  return kLightRange[kind].y;
#endif
}

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

// Light i of the buffer, of a kind known here (a constant: lightType(L) folds to it).
LightData lightOfKind(int i, const int kind) {
  LightData L = lights[i];
  L.colour_type.a = float(kind);
  return L;
}

// The loop over a kind's lights, `SHADE` the call for light L (one per kind of loop below).
// LIGHT_LOOPS_WRITTEN_OUT (defined by glintlab-shader-stats alone, src/shader_stats/) writes each
// loop out as two guarded calls, for scenes of at most two lights a kind: where shadeLight itself
// holds a loop the compiler cannot unroll (a per-pixel count), the light loop around it stays a
// loop, and a light's operations could not be told from the program's.
#ifdef LIGHT_LOOPS_WRITTEN_OUT
#define FOR_EACH_LIGHT_OF(kind, SHADE)                                                       \
  if (kLightRange[kind].x < kLightRange[kind].y) {                                           \
    LightData L = lightOfKind(kLightRange[kind].x, kind);                                    \
    addRadiance(sum, SHADE);                                                                 \
  }                                                                                          \
  if (kLightRange[kind].x + 1 < kLightRange[kind].y) {                                       \
    LightData L = lightOfKind(kLightRange[kind].x + 1, kind);                                \
    addRadiance(sum, SHADE);                                                                 \
  }
#else
#define FOR_EACH_LIGHT_OF(kind, SHADE)                                                       \
  for (int i = kLightRange[kind].x; i < lightRangeEnd(kind); ++i) {                          \
    LightData L = lightOfKind(i, kind);                                                      \
    addRadiance(sum, SHADE);                                                                 \
  }
#endif

// The lights of a compact kind.
Radiance shadeCompactLights(Surface s, const int kind) {
  Radiance sum = Radiance(vec3(0.0), vec3(0.0));
  FOR_EACH_LIGHT_OF(kind, shadeLight(s, L))
  return sum;
}

// The lights of a kind that is not compact.
Radiance shadeEnvironmentLights(Surface s, const int kind) {
  Radiance sum = Radiance(vec3(0.0), vec3(0.0));
  FOR_EACH_LIGHT_OF(kind, shadeEnvironmentLight(s, L))
  return sum;
}

#include "generated/shade_all_lights.glsl"
