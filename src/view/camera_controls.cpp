#include "view/camera_controls.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

namespace glintlab {

namespace {

constexpr float kPoleMarginDegrees = 1.0f;

/// `direction` turned by `yaw` about `up` and by `pitch` toward `up`, its elevation above the
/// plane normal to `up` kept within the pole margin.
glm::vec3 turn(glm::vec3 direction, glm::vec3 up, float yaw_degrees, float pitch_degrees) {
  up = glm::normalize(up);
  const float length = glm::length(direction);
  glm::vec3 d = direction / length;
  d = glm::angleAxis(glm::radians(yaw_degrees), up) * d;
  const float elevation = glm::degrees(std::asin(std::clamp(glm::dot(d, up), -1.0f, 1.0f)));
  const float limit = 90.0f - kPoleMarginDegrees;
  const float target = std::clamp(elevation + pitch_degrees, -limit, limit);
  glm::vec3 horizontal = d - glm::dot(d, up) * up;
  if (glm::length(horizontal) < 1e-6f) {
    // Looking straight along the up axis: any horizontal direction is the same view's heading.
    horizontal = std::abs(up.x) < 0.9f ? glm::cross(up, glm::vec3(1, 0, 0)) : glm::cross(up, glm::vec3(0, 0, 1));
  }
  horizontal = glm::normalize(horizontal);
  const float e = glm::radians(target);
  return length * (std::cos(e) * horizontal + std::sin(e) * up);
}

}  // namespace

Camera orbit_camera(const Camera& camera, float yaw_degrees, float pitch_degrees) {
  Camera c = camera;
  // The offset from the target turns; pitching the camera up moves it down, so the offset's
  // elevation changes by -pitch.
  c.position = c.target + turn(camera.position - camera.target, camera.up, yaw_degrees, -pitch_degrees);
  return c;
}

Camera dolly_camera(const Camera& camera, float factor) {
  Camera c = camera;
  factor = std::max(factor, 1e-3f);
  if (c.projection == Projection::Orthographic) {
    c.view_height *= factor;
    return c;
  }
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = std::max(glm::length(offset) * factor, 2.0f * camera.near_plane);
  c.position = camera.target + distance * glm::normalize(offset);
  return c;
}

Camera fly_camera(const Camera& camera, glm::vec3 move) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const glm::vec3 step = move.x * right + move.y * up + move.z * forward;
  Camera c = camera;
  c.position += step;
  c.target += step;
  return c;
}

Camera look_camera(const Camera& camera, float yaw_degrees, float pitch_degrees) {
  Camera c = camera;
  c.target = c.position + turn(camera.target - camera.position, camera.up, yaw_degrees, pitch_degrees);
  return c;
}

}  // namespace glintlab
