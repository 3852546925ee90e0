// Visible area lights: their emitted radiance (front face only, unless two-sided), counted in
// the total image but not in the specular one.
#include "core/frame.glsl"

uniform vec3 uRadiance;
uniform bool uTwoSided;

in vec3 vPosition;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUV;

layout(location = 0) out vec4 outTotal;
layout(location = 1) out vec4 outSpecular;

void main() {
  vec3 view = frame.camera_pos.w > 0.5 ? frame.camera_pos.xyz - vPosition : -frame.camera_forward.xyz;
  bool lit = uTwoSided || dot(vNormal, view) > 0.0;
  outTotal = vec4(lit ? uRadiance : vec3(0.0), 1.0);
  outSpecular = vec4(0.0, 0.0, 0.0, 1.0);
}
