#pragma once
// Material data (no shading code: shading lives in GLSL). Roughness is always alpha, never
// perceptual roughness; alpha = 0 is a perfect mirror.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>

#include "scene/normal_map.hpp"

namespace glintlab {

enum class Ndf { GGX = 0, Beckmann = 1 };

/// A glinty material (Chermain et al. 2020, 2021): a procedural, discrete Beckmann microsurface
/// whose limit at large footprints is the Beckmann NDF of slope deviations sigma and correlation rho.
struct GlintParams {
  float log_density = 20.0f;     ///< ln of the number of microfacets per unit of uv area
  float relative_area = 1.0f;    ///< fraction of the surface's cells that hold microfacets
  float max_anisotropy = 4.0f;   ///< clamp of the footprint ellipse's eccentricity (2021's default)
};

struct Material {
  std::string name;
  Ndf ndf = Ndf::GGX;
  glm::vec2 alpha{0.1f};          ///< (alpha_x along the tangent, alpha_y along the bitangent)
  float rho = 0.0f;               ///< slope correlation (glinty materials; alpha = sqrt(2) sigma)
  glm::vec3 f0{0.04f};            ///< Fresnel reflectance at normal incidence (Schlick)
  glm::vec3 diffuse{0.0f};        ///< Lambert albedo
  std::shared_ptr<const NormalMap> normal_map;  ///< optional tangent-space normal map
  float normal_map_tiling = 1.0f; ///< repeats of the normal map per unit of uv
  std::optional<GlintParams> glints;  ///< set for glinty materials (then ndf is Beckmann)
};

}  // namespace glintlab
