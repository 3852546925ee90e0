#pragma once
// A light of the scene: its kind (src/scene/lights/light_kind.hpp) and the parameters kinds read. Units
// (docs/scene-format.md): point and spot lights emit intensity [W/sr], directional lights and suns
// irradiance at normal incidence [W/m^2], area lights (disk, sphere, quad) and environments
// radiance [W/(m^2 sr)].
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>

namespace glintlab {

struct LightKind;
struct EnvironmentMap;

struct Light {
  const LightKind* kind = nullptr;   ///< set by the parser; never null in a scene
  glm::vec3 colour{1.0f};            ///< intensity, irradiance or radiance, by kind
  glm::vec3 position{0.0f};          ///< point, spot, disk, sphere, quad: centre
  glm::vec3 direction{0, -1, 0};     ///< directional, sun: travel direction; disk, quad: emitting normal; spot: axis
  glm::vec3 up{0, 0, 1};             ///< quad: orients the quad's second edge
  float radius = 0.0f;               ///< disk, sphere
  glm::vec2 size{1.0f};              ///< quad: edge lengths
  float angular_radius_degrees = 0;  ///< sun: half-angle of its disk
  float inner_angle_degrees = 0;     ///< spot: full intensity within this angle of the axis
  float outer_angle_degrees = 45;    ///< spot: no light beyond this angle (> inner, <= 90)
  bool visible = true;               ///< area lights, environments: seen by the camera
  float rotation_degrees = 0;        ///< environment: turn of its map about +y
  /// environment: its radiance map (colour scales it: the `intensity`); shared, as a scene's copies share it
  std::shared_ptr<const EnvironmentMap> environment;
};

}  // namespace glintlab
