// Transforms one shape's vertices to world and clip space (forward and emitter passes).
#include "core/frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUV;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPosition;
out vec3 vNormal;
out vec4 vTangent;
out vec2 vUV;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vPosition = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  // Mirroring transforms flip the frame's handedness.
  float mirrored = determinant(mat3(uModel)) < 0.0 ? -1.0 : 1.0;
  vTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w * mirrored);
  vUV = aUV;
  gl_Position = frame.view_proj * world;
}
