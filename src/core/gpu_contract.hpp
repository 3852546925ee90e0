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
/// Storage-buffer binding points of the materials' stored Gaussian elements (yan2016, deng2022's
/// fallback; src/prefilter/position_normal_elements.hpp, shaders/glints/normal-map/position_normal.glsl).
inline constexpr int kPositionNormalElementNormalsBinding = 2;
inline constexpr int kPositionNormalElementJacobiansBinding = 3;
/// Storage-buffer binding point of the environment's spherical Gaussian lobes (deng2022, yan2016;
/// shaders/glints/normal-map/environment_lobes.glsl).
inline constexpr int kEnvironmentLobesBinding = 4;
/// Storage-buffer binding points of the path tracer's shading pass (passes/path_direct.comp,
/// src/render/path_reference.cpp): its hits in; their shadow rays, emission and bounces out. After
/// the methods' own, which the backends path:<method> bind beside them: 9 storage blocks in one
/// compute program, past GL's guaranteed 8 (llvmpipe and NVIDIA's drivers have 16 or more).
inline constexpr int kPathHitsBinding = 5;
inline constexpr int kPathShadowRaysBinding = 6;
inline constexpr int kPathEmissionBinding = 7;
inline constexpr int kPathContinuationBinding = 8;

/// Texture units of a material's maps (shaders/core/fragment_inputs.glsl, slope_moments.glsl).
inline constexpr int kNormalMapUnit = 0;
inline constexpr int kSlopeMomentsUnit = 1;
inline constexpr int kSlopeCrossMomentUnit = 2;
/// Texture units of a textured material's parameters (shaders/core/material_textures.glsl).
inline constexpr int kBaseColorUnit = 3;
inline constexpr int kMetallicRoughnessUnit = 4;
inline constexpr int kEmissiveUnit = 5;
/// Texture units of the scene's environment light (its `environment-map` resource,
/// src/render/resources/environment_map_resource.cpp; shaders/lights/environment.glsl and
/// shaders/lobe/environment_shading.glsl): its radiance map, the CDFs that sample it, the
/// GGX-prefiltered mip chain and the irradiance map of the split sum.
inline constexpr int kEnvironmentRadianceUnit = 6;
inline constexpr int kEnvironmentCdfUnit = 7;
inline constexpr int kEnvironmentSpecularUnit = 8;
inline constexpr int kEnvironmentIrradianceUnit = 9;
/// Texture unit of the environment's luminance-level weights for glints under it, prefiltered as
/// the specular chain (its `environment-glint-weights` resource, kneiphof2025's;
/// shaders/glints/binomial/environment_glints.glsl).
inline constexpr int kEnvironmentGlintWeightsUnit = 10;
/// Per-draw texture transforms (uTextureTransforms in shaders/core/material.glsl), by slot.
inline constexpr int kTextureSlotNormalMap = 0;
inline constexpr int kTextureSlotBaseColor = 1;
inline constexpr int kTextureSlotMetallicRoughness = 2;
inline constexpr int kTextureSlotEmissive = 3;
inline constexpr int kTextureSlots = 4;
/// Units from here on hold the precomputed tables, in their registry's order
/// (src/tables/registry.cpp); GLSL sees each as TABLE_UNIT_<ID>.
inline constexpr int kFirstTableUnit = 11;

/// MaterialGpu::f0_ndf.w: the microfacet distribution.
inline constexpr int kNdfGgx = 0;
inline constexpr int kNdfBeckmann = 1;

/// The surface a reference pass gives stochastic materials (the forward pass's REFERENCE_SURFACE;
/// docs/methods.md#kneiphof2024, "Two references" and "A surface of facets"): the material's own
/// model, one fixed realisation of the binomial microfacets, or a fixed field of mirror facets.
enum class ReferenceSurface { Model = 0, Realisation = 1, Facets = 2 };

/// The std140 records below are each declared once, as a list of fields (type, name, meaning):
/// the C++ struct is made from the list here, and the GLSL struct of the same name and fields by
/// src/render/shader_contract.cpp (generated/gpu_structs.glsl), so that neither side restates the
/// other. Every field is a vec4, ivec4 or mat4: std140 then packs them as C++ does (no padding).
struct Std140Field {
  const char* glsl_type;
  const char* name;
  const char* meaning;
};
#define GLINTLAB_STD140_MEMBER(type, name, meaning) glm::type name;
#define GLINTLAB_STD140_FIELD(type, name, meaning) Std140Field{#type, #name, meaning},

/// One light (LightData in GLSL, in a uniform buffer: shaders/lights/light_data.glsl). What each
/// field holds is the kind's (src/scene/lights/<kind>.cpp packs it, shaders/lights/<kind>.glsl
/// reads it); colour_type.w is always the kind's code.
#define GLINTLAB_LIGHT_FIELDS(X)                                                                     \
  X(vec4, colour_type, "rgb: intensity, irradiance or radiance (by kind); a: the kind's code (LIGHT_<KIND>)") \
  X(vec4, position_radius, "the kind's")                                                           \
  X(vec4, direction_cos, "the kind's")                                                             \
  X(vec4, axis_u, "the kind's")                                                                    \
  X(vec4, axis_v, "the kind's")
struct LightGpu {
  GLINTLAB_LIGHT_FIELDS(GLINTLAB_STD140_MEMBER)
};
inline constexpr Std140Field kLightFields[] = {GLINTLAB_LIGHT_FIELDS(GLINTLAB_STD140_FIELD)};
static_assert(sizeof(LightGpu) == 80);
static_assert(kMaxLights * sizeof(LightGpu) <= 16384, "the light block must fit GL's minimum uniform block size");

/// One material (MaterialData in GLSL: shaders/core/material.glsl). kind_params holds the
/// material kind's own parameters in the order its descriptor declares them; GLSL reads them
/// through accessors generated from that declaration (src/scene/materials/material_kind.hpp).
#define GLINTLAB_MATERIAL_FIELDS(X)                                                                    \
  X(vec4, f0_ndf, "rgb: Schlick F0; a: the NDF (NDF_GGX or NDF_BECKMANN)")                           \
  X(vec4, diffuse_tiling, "rgb: Lambert albedo; a: normal-map repeats per uv unit")                  \
  X(vec4, alpha_rho, "xy: alpha; z: slope correlation rho; w: anisotropy rotation (radians, tangent to bitangent)") \
  X(vec4, kind_params, "the material kind's parameters, in its declaration's order")                \
  X(vec4, emission, "rgb: emitted radiance")                                                        \
  X(vec4, base_color, "textured materials (MATERIAL_TEXTURES): rgba factor of the base colour")      \
  X(vec4, metal_rough, "textured materials: x: metallic; y: perceptual roughness; z: anisotropy strength") \
  X(vec4, dielectric_f0, "textured materials: rgb: f0 of the non-metal part")
struct MaterialGpu {
  GLINTLAB_MATERIAL_FIELDS(GLINTLAB_STD140_MEMBER)
};
inline constexpr Std140Field kMaterialFields[] = {GLINTLAB_MATERIAL_FIELDS(GLINTLAB_STD140_FIELD)};
static_assert(sizeof(MaterialGpu) == 128);
static_assert(kMaxMaterials * sizeof(MaterialGpu) <= 16384, "the material block must fit GL's minimum uniform block size");

/// Per-frame data, the same for every draw (the block `frame` in GLSL: shaders/core/frame.glsl).
#define GLINTLAB_FRAME_FIELDS(X)                                                             \
  X(mat4, view_proj, "world to clip space")                                                \
  X(vec4, camera_pos, "xyz: camera position (world); w: 1 perspective, 0 orthographic")    \
  X(vec4, camera_forward, "xyz: the view direction (orthographic cameras)")                \
  X(ivec4, target, "xy: render-target size (pixels); z: sub-pixels per axis k; w: 0, a zero no compiler can see (rolled loops)") \
  X(ivec4, tile, "xy: tile origin in sub-pixels of the whole film; z: light samples; w: seed")
struct FrameUniforms {
  GLINTLAB_FRAME_FIELDS(GLINTLAB_STD140_MEMBER)
};
inline constexpr Std140Field kFrameFields[] = {GLINTLAB_FRAME_FIELDS(GLINTLAB_STD140_FIELD)};
static_assert(sizeof(FrameUniforms) == 128);

/// Bytes of a std140 member of these types (all 16-byte aligned); the records' sizes are their sums.
constexpr std::size_t std140_size(const char* type) {
  return type[0] == 'm' ? 64 : 16;  // mat4 or a 4-vector
}
template <std::size_t N>
constexpr std::size_t std140_record_size(const Std140Field (&fields)[N]) {
  std::size_t size = 0;
  for (const Std140Field& f : fields) size += std140_size(f.glsl_type);
  return size;
}
static_assert(std140_record_size(kLightFields) == sizeof(LightGpu));
static_assert(std140_record_size(kMaterialFields) == sizeof(MaterialGpu));
static_assert(std140_record_size(kFrameFields) == sizeof(FrameUniforms));

}  // namespace glintlab
