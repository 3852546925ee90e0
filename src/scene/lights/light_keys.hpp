#pragma once
// Pieces the light kinds' descriptors share: bounds of their keys, directions, orientation of
// emitter meshes.
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "scene/lights/light.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab::light_keys {

inline constexpr double kMaxPower = 1e9;   // bound on intensities, irradiances and radiances
inline constexpr double kMaxLength = 1e6;  // bound on lengths, in scene units (as for shapes)

/// A required, non-zero direction, normalised.
inline glm::vec3 require_direction(TomlReader& r, const std::string& key) {
  const glm::vec3 d = r.require_vec3(key);
  if (glm::length(d) < 1e-9f) r.fail(key, "value is a zero vector; allowed: any non-zero vector");
  return glm::normalize(d);
}

/// The keys every area light has: its centre `position`, its `radiance` and whether it is
/// `visible` to the camera as an emitter.
inline Light parse_area_light(TomlReader& r) {
  Light l;
  l.position = r.require_vec3("position");
  l.colour = r.get_colour("radiance", glm::vec3(1.0f), 0.0, kMaxPower);
  l.visible = r.get_bool("visible", true);
  return l;
}

/// Rotation taking +y to `n` (the mesh generators build disks and planes facing +y).
inline glm::mat4 orient_y_to(glm::vec3 n, glm::vec3 up_hint) {
  glm::vec3 x = glm::cross(up_hint, n);
  if (glm::length(x) < 1e-6f) x = glm::cross(glm::vec3(1, 0, 0), n);
  if (glm::length(x) < 1e-6f) x = glm::cross(glm::vec3(0, 0, 1), n);
  x = glm::normalize(x);
  const glm::vec3 z = glm::cross(x, n);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x, 0);
  m[1] = glm::vec4(n, 0);
  m[2] = glm::vec4(z, 0);
  return m;
}

}  // namespace glintlab::light_keys
