#pragma once
// Material data (no shading code: shading lives in GLSL). Roughness is always alpha, never
// perceptual roughness; alpha = 0 is a perfect mirror.
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

enum class Ndf { GGX = 0, Beckmann = 1 };

/// A glinty material (Chermain et al. 2020, 2021): a procedural, discrete Beckmann microsurface
/// whose limit at large footprints is the Beckmann NDF of slope deviations sigma and correlation rho.
struct GlintParams {
  float log_density = 20.0f;     ///< ln of the number of microfacets per unit of uv area
  float relative_area = 1.0f;    ///< fraction of the surface's cells that hold microfacets
  float max_anisotropy = 4.0f;   ///< clamp of the footprint ellipse's eccentricity (2021's default)
};

/// A glinty material of Deliot & Belcour 2023 (binomial laws on anisotropic grids): discrete
/// microfacets counted by a binomial law whose expectation is the smooth GGX NDF of the material's
/// alpha (docs/methods.md#deliot2023). Other methods shade its smooth GGX limit.
struct BinomialGlintParams {
  float log_density = 20.0f;           ///< ln of the number of microfacets per unit of uv area
  float microfacet_roughness = 0.02f;  ///< the paper's R: p = R D(h) / D(0), a facet's share of the lobe
  float density_randomization = 0.0f;  ///< standard deviation of ln density between surface cells
  float slope_grid_scale = 16.0f;      ///< slope cells per unit of the projected half vector h.xy
};

/// A normal-map-glints material (Yan et al. 2016's microsurface): the normal map itself is the
/// surface; at a point u the projected normal s = h.xy is Gaussian about the map's bilinear normal
/// n(u).xy with standard deviation `intrinsic_roughness` per axis (docs/scene-format.md). Other
/// methods shade its Beckmann limit alpha = sqrt(2) sigma_r over the normal map.
struct NormalGlintParams {
  float intrinsic_roughness = 0.01f;  ///< sigma_r
  /// Beckmann alpha of the whole microsurface, sqrt(E[|b|^2] + 2 sigma_r^2) with b = n.xy / n.z
  /// over the map's texels: used only for Smith masking-shadowing.
  float masking_alpha = 0.01f;
};

/// An 8-bit RGBA texture of material parameters, row 0 at v = 0 (glintlab's uv: v up, so an image
/// file's bottom row comes first).
struct MaterialTexture {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  bool srgb = false;        ///< colour data (decoded to linear by the sampler) or linear data
  std::string description;  ///< where it came from
};

/// A texture and the affine map from the surface's uv to its coordinates (KHR_texture_transform).
struct TextureSlot {
  std::shared_ptr<const MaterialTexture> texture;  ///< null: the factor alone (a white texel)
  glm::mat3 transform{1.0f};
};

/// glTF's metallic-roughness model with textures: per texel, factor x texel gives the base colour,
/// metallic and perceptual roughness r, from which the shader derives alpha = r^2 (widened along
/// the anisotropy direction: alpha_x = mix(alpha, 1, anisotropy^2)), f0 and the Lambert albedo.
struct TexturedMetalRough {
  glm::vec4 base_color{1.0f};
  float metallic = 1.0f;
  float roughness = 1.0f;
  float anisotropy = 0.0f;          ///< KHR_materials_anisotropy's strength
  glm::vec3 dielectric_f0{0.04f};   ///< f0 of the non-metal part (KHR_materials_ior, _specular)
  TextureSlot base_color_texture;   ///< rgb (sRGB)
  TextureSlot metallic_roughness_texture;  ///< g: roughness, b: metallic (linear)
  TextureSlot emissive_texture;     ///< rgb (sRGB), times Material::emission
};

struct Material {
  std::string name;
  Ndf ndf = Ndf::GGX;
  glm::vec2 alpha{0.1f};          ///< (alpha_x along the anisotropy direction, alpha_y across it)
  float anisotropy_rotation = 0;  ///< radians from the tangent (+u) towards the bitangent (+v)
  float rho = 0.0f;               ///< slope correlation (glinty materials; alpha = sqrt(2) sigma)
  glm::vec3 f0{0.04f};            ///< Fresnel reflectance at normal incidence (Schlick)
  glm::vec3 diffuse{0.0f};        ///< Lambert albedo
  glm::vec3 emission{0.0f};       ///< emitted radiance [W/(m^2 sr)], added to every method's image
  std::shared_ptr<const NormalMap> normal_map;  ///< optional tangent-space normal map
  float normal_map_tiling = 1.0f; ///< repeats of the normal map per unit of uv
  glm::mat3 normal_map_transform{1.0f};  ///< then this affine map of uv (KHR_texture_transform)
  std::optional<GlintParams> glints;  ///< set for glinty materials (then ndf is Beckmann)
  std::optional<BinomialGlintParams> binomial_glints;  ///< set for binomial-glints materials (ndf GGX)
  /// Set for normal-map-glints materials (then ndf is Beckmann, alpha sqrt(2) sigma_r, normal_map set).
  std::optional<NormalGlintParams> normal_glints;
  /// Set for materials whose parameters vary per texel (glTF); then f0, diffuse and alpha above
  /// are those of the factors alone.
  std::optional<TexturedMetalRough> textures;
};

}  // namespace glintlab
