// The forward pass's per-fragment inputs: interpolated vertex attributes (passes/forward.vert)
// and the draw's material. Declared before the method module, so that a method may re-evaluate
// the attributes elsewhere in the pixel (interpolateAtOffset; see common/pixel_corners.glsl).
#include "common/material.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUV;

layout(binding = 0) uniform sampler2D uNormalMap;
uniform int uMaterial;

// Normal-map coordinates of a uv (the material's tiling applied).
vec2 normalMapCoordinates(vec2 uv) { return uv * materials[uMaterial].diffuse_tiling.a; }
