// Material data, one entry per scene material (std140 uniform buffer; MaterialGpu in
// src/core/gpu_contract.hpp, filled by src/render/gpu_scene.cpp). A uniform buffer for the reason
// given in lights/light_data.glsl. MAX_MATERIALS, the binding and NDF_GGX / NDF_BECKMANN (the
// codes in f0_ndf.a) are the contract's.
#include "generated/gpu_contract.glsl"

struct MaterialData {
  vec4 f0_ndf;          // rgb: Schlick F0; a: 0 GGX, 1 Beckmann
  vec4 diffuse_tiling;  // rgb: Lambert albedo; a: normal-map repeats per uv unit
  vec4 alpha_rho;       // xy: alpha_x, alpha_y; z: slope correlation rho; w: anisotropy rotation
                        // (radians, from the tangent towards the bitangent)
  vec4 glints;          // glinty materials (a program variant, MATERIAL_GLINTS): x: ln microfacets
                        // per uv area; y: relative area; z: max anisotropy; w: unused.
                        // Binomial glints (MATERIAL_BINOMIAL_GLINTS): x: ln microfacets per uv
                        // area; y: microfacet roughness R; z: density randomization; w: slope
                        // cells per unit of h.xy.
                        // Normal-map glints (MATERIAL_NORMAL_GLINTS): x: intrinsic roughness
                        // sigma_r; y: masking alpha (Beckmann, for Smith G2 only); zw: unused
  vec4 emission;        // rgb: emitted radiance; w: unused
  // Textured materials (a program variant, MATERIAL_TEXTURES; core/material_textures.glsl):
  vec4 base_color;      // rgba: factor of the base-colour texture
  vec4 metal_rough;     // x: metallic factor; y: perceptual-roughness factor; z: anisotropy strength
  vec4 dielectric_f0;   // rgb: f0 of the non-metal part
};
layout(std140, binding = MATERIAL_BLOCK_BINDING) uniform MaterialBlock { MaterialData materials[MAX_MATERIALS]; };

// Per draw: the affine maps from the surface's uv to each of the draw's material textures'
// coordinates (the normal map's tiling; KHR_texture_transform), indexed by TEXTURE_SLOT_*.
uniform mat3x2 uTextureTransforms[TEXTURE_SLOTS];
