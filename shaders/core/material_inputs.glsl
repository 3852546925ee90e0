// The draw's material as every pass that shades a surface reads it (the forward pass per fragment,
// the path tracer's shading per hit): its entry in the material block, its normal map (as a surface
// of texels: core/normal_map.glsl) and the normal map's coordinates.
#include "core/material.glsl"
#include "generated/gpu_contract.glsl"

layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uNormalMap;
#ifdef EXPORTED_SHADER
int uMaterial;  // set by an exported shader's entry point from its argument (export/shade_pixel.frag)
#else
uniform int uMaterial;
#endif

// Normal-map coordinates of a uv (the material's tiling and texture transform applied).
vec2 normalMapCoordinates(vec2 uv) { return uTextureTransforms[TEXTURE_SLOT_NORMAL_MAP] * vec3(uv, 1.0); }

#include "core/normal_map.glsl"
