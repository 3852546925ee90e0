// Per-frame data, the same for every draw (std140; FrameData is generated from FrameUniforms's
// field list in src/core/gpu_contract.hpp).
#include "generated/gpu_contract.glsl"
#include "generated/gpu_structs.glsl"

layout(std140, binding = FRAME_BLOCK_BINDING) uniform FrameBlock { FrameData frame; };

// Unit vector from p towards the camera (for an orthographic camera, against its view direction).
vec3 viewDirectionFrom(vec3 p) { return frame.camera_pos.w > 0.5 ? normalize(frame.camera_pos.xyz - p) : -frame.camera_forward.xyz; }
