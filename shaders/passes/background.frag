// What camera rays that miss the scene see: a visible environment light's radiance in the ray's
// direction, read as the light is (texel for texel, shaders/lights/environment.glsl), in the total
// image but not the specular one (as emitters: passes/emitter.frag). The ray through this fragment
// comes from the frame's own view-projection, so sub-pixel tiles of the reference get their own rays.
#include "core/frame.glsl"
#include "lights/lights.glsl"

uniform int uLight;        // the environment's index in the light block
uniform mat4 uClipToWorld;  // inverse(frame.view_proj), once per draw on the CPU

in vec2 vNdc;

layout(location = 0) out vec4 outTotal;
layout(location = 1) out vec4 outSpecular;

void main() {
  vec4 near = uClipToWorld * vec4(vNdc, -1.0, 1.0), far = uClipToWorld * vec4(vNdc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  outTotal = vec4(lightRadianceFrom(lights[uLight], dir), 1.0);
  outSpecular = vec4(0.0, 0.0, 0.0, 1.0);
}
