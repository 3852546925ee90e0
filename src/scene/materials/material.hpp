#pragma once
// Material data (no shading code: shading lives in GLSL). Roughness is always alpha, never
// perceptual roughness; alpha = 0 is a perfect mirror. What a material is beyond its microfacet
// lobe is its kind's (src/scene/materials/material_kind.hpp): glints, and the parameters that make them.
#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/materials/material_kind.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

enum class Ndf { GGX = 0, Beckmann = 1 };

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
  /// What the material is: its registered kind (microfacet, glinty, binomial-glints, ...).
  const MaterialKind* kind = &default_material_kind();
  /// The kind's own parameters, in the order it declares them (MaterialKind::params).
  std::array<float, kMaxMaterialKindParams> kind_params{};
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
  /// Set for materials whose parameters vary per texel (glTF); then f0, diffuse and alpha above
  /// are those of the factors alone.
  std::optional<TexturedMetalRough> textures;

  /// Whether its smooth lobe can be anisotropic anywhere on the surface (the program variant
  /// MATERIAL_ANISOTROPIC): unequal alphas, a slope correlation, or glTF's anisotropy.
  [[nodiscard]] bool anisotropic() const {
    return rho != 0.0f || (textures ? textures->anisotropy != 0.0f : alpha.x != alpha.y);
  }
  /// Whether the material is of the kind `id`.
  [[nodiscard]] bool is(std::string_view id) const { return kind->id == id; }
  /// One of the kind's parameters by key; throws std::logic_error if the kind declares none such.
  [[nodiscard]] float kind_param(std::string_view key) const {
    return kind_params[static_cast<std::size_t>(kind->param_index(key))];
  }
  void set_kind_param(std::string_view key, float value) {
    kind_params[static_cast<std::size_t>(kind->param_index(key))] = value;
  }
  /// The kind and its parameters at their defaults.
  void set_kind(const MaterialKind& k) {
    kind = &k;
    kind_params = {};
    for (std::size_t i = 0; i < k.params.size(); ++i) kind_params[i] = k.params[i].default_value;
  }
};

}  // namespace glintlab
