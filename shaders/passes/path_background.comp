// What the path tracer's camera rays that miss the scene see: a visible environment's radiance in
// their direction, read as passes/background.frag reads it for the raster passes.
layout(local_size_x = 64) in;

#include "lights/lights.glsl"

// In: each ray's direction (xyz); out: the radiance it sees (rgb).
layout(std430, binding = PATH_HITS_BINDING) buffer PathMisses { vec4 missed[]; };

uniform int uLight;  // the environment's index in the light block
uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  missed[i] = vec4(lightRadianceFrom(lights[uLight], missed[i].xyz), 0.0);
}
