// Per-frame data, the same for every draw (std140; FrameUniforms in src/core/gpu_contract.hpp).
#include "generated/gpu_contract.glsl"

layout(std140, binding = FRAME_BLOCK_BINDING) uniform FrameBlock {
  mat4 uViewProj;
  vec4 uCameraPos;     // xyz: camera position (world); w: 1 perspective, 0 orthographic
  vec4 uCameraForward; // xyz: view direction for orthographic cameras
  ivec4 uTarget;       // xy: render-target size (pixels); z: sub-pixels per axis k; w: unused
  ivec4 uTile;         // xy: tile origin in sub-pixels of the whole film; z: light samples; w: seed
};

// Unit vector from p towards the camera (for an orthographic camera, against its view direction).
vec3 viewDirectionFrom(vec3 p) { return uCameraPos.w > 0.5 ? normalize(uCameraPos.xyz - p) : -uCameraForward.xyz; }
