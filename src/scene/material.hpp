#pragma once
// Material data (no shading code: shading lives in GLSL). Roughness is always alpha, never
// perceptual roughness; alpha = 0 is a perfect mirror.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>

#include "scene/normal_map.hpp"

namespace glintlab {

enum class Ndf { GGX = 0, Beckmann = 1 };

struct Material {
  std::string name;
  Ndf ndf = Ndf::GGX;
  glm::vec2 alpha{0.1f};          ///< (alpha_x along the tangent, alpha_y along the bitangent)
  glm::vec3 f0{0.04f};            ///< Fresnel reflectance at normal incidence (Schlick)
  glm::vec3 diffuse{0.0f};        ///< Lambert albedo
  std::shared_ptr<const NormalMap> normal_map;  ///< optional tangent-space normal map
  float normal_map_tiling = 1.0f; ///< repeats of the normal map per unit of uv
};

}  // namespace glintlab
