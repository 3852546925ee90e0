// Material data, one entry per scene material (std140 uniform buffer; MaterialData is generated
// from MaterialGpu's field list in src/core/gpu_contract.hpp, filled by src/render/gpu_scene.cpp).
// A uniform buffer for the reason given in lights/light_data.glsl. MAX_MATERIALS, the binding and
// NDF_GGX / NDF_BECKMANN (the codes in f0_ndf.a) are the contract's; kind_params is read through
// the accessors generated from each material kind's declaration (generated/material_params.glsl).
#include "generated/gpu_contract.glsl"
#include "generated/gpu_structs.glsl"

layout(std140, binding = MATERIAL_BLOCK_BINDING) uniform MaterialBlock { MaterialData materials[MAX_MATERIALS]; };

// Per draw: the affine maps from the surface's uv to each of the draw's material textures'
// coordinates (the normal map's tiling; KHR_texture_transform), indexed by TEXTURE_SLOT_*.
#ifdef EXPORTED_SHADER
// A block in an exported shader: Vulkan's GLSL, which HLSL and MSL are made from, has no loose uniforms.
layout(std140, binding = TEXTURE_TRANSFORM_BLOCK_BINDING) uniform TextureTransformBlock {
  mat3x2 uTextureTransforms[TEXTURE_SLOTS];
};
#else
uniform mat3x2 uTextureTransforms[TEXTURE_SLOTS];
#endif

#include "generated/material_params.glsl"
