// One light as the shaders receive it: LightData, generated from LightGpu's field list in
// src/core/gpu_contract.hpp, in a std140 uniform
// buffer. What each field holds is the kind's: src/scene/lights/<kind>.cpp packs it and
// shaders/lights/<kind>.glsl reads it; colour_type.a is always the kind's code (LIGHT_<KIND>).
// A uniform buffer, not a storage buffer: its loads are scalar, and drivers that mask storage
// loads in helper invocations (llvmpipe) would otherwise break screen-space derivatives of
// anything computed from a light.
#include "core/constants.glsl"
#include "generated/gpu_contract.glsl"
#include "generated/gpu_structs.glsl"

layout(std140, binding = LIGHT_BLOCK_BINDING) uniform LightBlock { LightData lights[MAX_LIGHTS]; };

const float FAR_AWAY = 1e30;

int lightType(LightData L) { return int(L.colour_type.a); }
