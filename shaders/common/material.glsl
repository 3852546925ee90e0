// Material data, one entry per scene material (std430, binding 2; see src/render/gpu_scene.cpp).
struct MaterialData {
  vec4 f0_ndf;          // rgb: Schlick F0; a: 0 GGX, 1 Beckmann
  vec4 diffuse_tiling;  // rgb: Lambert albedo; a: normal-map repeats per uv unit
  vec4 alpha_flags;     // xy: alpha_x, alpha_y; z: 1 if the material has a normal map
};
layout(std430, binding = 2) readonly buffer MaterialBlock { MaterialData materials[]; };

const int NDF_GGX = 0;
const int NDF_BECKMANN = 1;
