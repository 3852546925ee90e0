// A shading module that returns nothing: `glintlab bench` draws the scene with it to measure the
// fixed cost of a frame (clears, vertex work, rasterisation and the surface record), which no
// method can go below. Included in place of a method module; not a method.
#define METHOD_SHADES_ENVIRONMENT  // as nothing, like every light
#include "lights/lights.glsl"
#include "core/surface.glsl"

void prepareSurface(inout Surface s) {}

Radiance shadeLight(Surface s, LightData L) { return Radiance(vec3(0.0), s.normal * 1e-30); }
