#pragma once
// Lights. Units (docs/scene-format.md): point lights emit intensity [W/sr], directional lights
// irradiance at normal incidence [W/m^2], area lights (disk, sphere, quad) radiance [W/(m^2 sr)].
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace glintlab {

enum class LightType { Point = 0, Directional = 1, Disk = 2, Sphere = 3, Quad = 4 };

struct Light {
  LightType type = LightType::Point;
  glm::vec3 colour{1.0f};            ///< intensity, irradiance or radiance, by type
  glm::vec3 position{0.0f};          ///< point, disk, sphere, quad: centre
  glm::vec3 direction{0, -1, 0};     ///< directional: travel direction; disk, quad: emitting normal
  glm::vec3 up{0, 0, 1};             ///< quad: orients the quad's second edge
  float radius = 0.0f;               ///< disk, sphere
  glm::vec2 size{1.0f};              ///< quad: edge lengths
  float angular_radius_degrees = 0;  ///< directional: 0 is a delta light, > 0 a distant disk
  bool visible = true;               ///< area lights: drawn as emitters seen by the camera

  [[nodiscard]] bool is_area() const { return type == LightType::Disk || type == LightType::Sphere || type == LightType::Quad; }
};

}  // namespace glintlab
