// Material data, one entry per scene material (std140 uniform buffer, binding 2; see
// src/render/gpu_scene.cpp). A uniform buffer for the reason given in common/lights.glsl;
// MAX_MATERIALS mirrors kMaxMaterials in src/scene/scene.hpp.
struct MaterialData {
  vec4 f0_ndf;          // rgb: Schlick F0; a: 0 GGX, 1 Beckmann
  vec4 diffuse_tiling;  // rgb: Lambert albedo; a: normal-map repeats per uv unit
  vec4 alpha_rho;       // xy: alpha_x, alpha_y; z: slope correlation rho; w: unused
  vec4 glints;          // glinty materials (a program variant, MATERIAL_GLINTS): x: ln microfacets
                        // per uv area; y: relative area; z: max anisotropy; w: unused
};
#define MAX_MATERIALS 256
layout(std140, binding = 2) uniform MaterialBlock { MaterialData materials[MAX_MATERIALS]; };

const int NDF_GGX = 0;
const int NDF_BECKMANN = 1;
