#pragma once
// The contract between the C++ side and the shaders: limits, binding points, texture units, codes
// and the std140 layouts of the uniform blocks. The shaders never restate it: they include
// generated/gpu_contract.glsl, written from these constants (src/render/shader_contract.cpp), and
// tests/glsl/test_gpu_contract.cpp checks the defines and the driver's std140 offsets against them.
// Light kinds' codes are their positions in the registry (src/scene/lights/light_kinds.cpp).
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace glintlab {

/// Limits of one scene: lights and materials live in uniform buffers (16 KiB, the minimum every
/// GL 4.5 driver offers; uniform, not storage, buffers: see shaders/lights/light_data.glsl).
inline constexpr int kMaxLights = 128;
inline constexpr int kMaxMaterials = 128;

/// Uniform-buffer binding points.
inline constexpr int kFrameBlockBinding = 0;
inline constexpr int kLightBlockBinding = 1;
inline constexpr int kMaterialBlockBinding = 2;
/// Storage-buffer binding points of the materials' prefiltered NDF pyramids (deng2022;
/// src/prefilter/prefiltered_ndf_layout.hpp, shaders/glints/normal-map/prefiltered_ndf.glsl).
inline constexpr int kPrefilteredNdfRecordsBinding = 0;
inline constexpr int kPrefilteredNdfValuesBinding = 1;

/// Texture units of a material's maps (shaders/core/fragment_inputs.glsl, slope_moments.glsl).
inline constexpr int kNormalMapUnit = 0;
inline constexpr int kSlopeMomentsUnit = 1;
inline constexpr int kSlopeCrossMomentUnit = 2;
/// Texture units of a textured material's parameters (shaders/core/material_textures.glsl).
inline constexpr int kBaseColorUnit = 3;
inline constexpr int kMetallicRoughnessUnit = 4;
inline constexpr int kEmissiveUnit = 5;
/// Per-draw texture transforms (uTextureTransforms in shaders/core/material.glsl), by slot.
inline constexpr int kTextureSlotNormalMap = 0;
inline constexpr int kTextureSlotBaseColor = 1;
inline constexpr int kTextureSlotMetallicRoughness = 2;
inline constexpr int kTextureSlotEmissive = 3;
inline constexpr int kTextureSlots = 4;
/// Units from here on hold the precomputed tables, in their registry's order
/// (src/tables/registry.cpp); GLSL sees each as TABLE_UNIT_<ID>.
inline constexpr int kFirstTableUnit = 6;

/// MaterialGpu::f0_ndf.w: the microfacet distribution.
inline constexpr int kNdfGgx = 0;
inline constexpr int kNdfBeckmann = 1;

/// One light: LightData in shaders/lights/light_data.glsl (std140: five vec4, no padding). What
/// each field holds is the kind's (src/scene/lights/<kind>.cpp packs it, shaders/lights/<kind>.glsl
/// reads it); colour_type.w is always the kind's code.
struct LightGpu {
  glm::vec4 colour_type;
  glm::vec4 position_radius;
  glm::vec4 direction_cos;
  glm::vec4 axis_u;
  glm::vec4 axis_v;
};
static_assert(sizeof(LightGpu) == 80);
static_assert(offsetof(LightGpu, colour_type) == 0 && offsetof(LightGpu, position_radius) == 16 &&
              offsetof(LightGpu, direction_cos) == 32 && offsetof(LightGpu, axis_u) == 48 &&
              offsetof(LightGpu, axis_v) == 64);
static_assert(kMaxLights * sizeof(LightGpu) <= 16384, "the light block must fit GL's minimum uniform block size");

/// One material: MaterialData in shaders/core/material.glsl (std140).
struct MaterialGpu {
  glm::vec4 f0_ndf;          ///< rgb: Schlick F0; a: kNdfGgx or kNdfBeckmann
  glm::vec4 diffuse_tiling;  ///< rgb: Lambert albedo; a: normal-map repeats per uv unit
  glm::vec4 alpha_rho;       ///< xy: alpha; z: slope correlation; w: anisotropy rotation (radians)
  glm::vec4 glints;          ///< x: ln density; y: relative area; z: max anisotropy (MATERIAL_GLINTS);
                             ///< binomial glints (MATERIAL_BINOMIAL_GLINTS): x: ln density; y: R;
                             ///< z: density randomization; w: slope-grid scale;
                             ///< normal-map glints (MATERIAL_NORMAL_GLINTS): x: sigma_r; y: masking alpha
  glm::vec4 emission;        ///< rgb: emitted radiance
  // Textured materials (a program variant, MATERIAL_TEXTURES): per-texel parameters' factors.
  glm::vec4 base_color;      ///< rgba factor
  glm::vec4 metal_rough;     ///< x: metallic; y: perceptual roughness; z: anisotropy strength
  glm::vec4 dielectric_f0;   ///< rgb: f0 of the non-metal part
};
static_assert(sizeof(MaterialGpu) == 128);
static_assert(offsetof(MaterialGpu, f0_ndf) == 0 && offsetof(MaterialGpu, diffuse_tiling) == 16 &&
              offsetof(MaterialGpu, alpha_rho) == 32 && offsetof(MaterialGpu, glints) == 48 &&
              offsetof(MaterialGpu, emission) == 64 && offsetof(MaterialGpu, base_color) == 80 &&
              offsetof(MaterialGpu, metal_rough) == 96 && offsetof(MaterialGpu, dielectric_f0) == 112);
static_assert(kMaxMaterials * sizeof(MaterialGpu) <= 16384, "the material block must fit GL's minimum uniform block size");

/// Per-frame data: FrameBlock in shaders/core/frame.glsl (std140).
struct FrameUniforms {
  glm::mat4 view_proj;
  glm::vec4 camera_pos;      ///< w: 1 perspective, 0 orthographic
  glm::vec4 camera_forward;
  glm::ivec4 target;         ///< xy: render-target size; z: sub-pixels per axis
  glm::ivec4 tile;           ///< xy: tile origin in sub-pixels; z: light samples; w: seed
};
static_assert(sizeof(FrameUniforms) == 128);
static_assert(offsetof(FrameUniforms, view_proj) == 0 && offsetof(FrameUniforms, camera_pos) == 64 &&
              offsetof(FrameUniforms, camera_forward) == 80 && offsetof(FrameUniforms, target) == 96 &&
              offsetof(FrameUniforms, tile) == 112);

}  // namespace glintlab
