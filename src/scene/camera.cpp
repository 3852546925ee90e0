#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include "core/hash.hpp"

namespace glintlab {

glm::mat4 Camera::view_matrix() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection_matrix(float aspect) const {
  if (projection == Projection::Perspective)
    return glm::perspective(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
  const float h = 0.5f * view_height;
  const float w = h * aspect;
  return glm::ortho(-w, w, -h, h, near_plane, far_plane);
}

glm::mat4 Camera::tile_projection_matrix(glm::ivec2 film, glm::ivec2 origin, glm::ivec2 size) const {
  const glm::mat4 full = projection_matrix(static_cast<float>(film.x) / static_cast<float>(film.y));
  // NDC of the tile's edges in the full film (y up in NDC, y down in pixels).
  const float x0 = -1.0f + 2.0f * static_cast<float>(origin.x) / static_cast<float>(film.x);
  const float x1 = -1.0f + 2.0f * static_cast<float>(origin.x + size.x) / static_cast<float>(film.x);
  const float y1 = 1.0f - 2.0f * static_cast<float>(origin.y) / static_cast<float>(film.y);
  const float y0 = 1.0f - 2.0f * static_cast<float>(origin.y + size.y) / static_cast<float>(film.y);
  // Affine remap of [x0,x1] x [y0,y1] onto [-1,1]^2, applied in clip space (scale w-linearly).
  glm::mat4 remap(1.0f);
  remap[0][0] = 2.0f / (x1 - x0);
  remap[1][1] = 2.0f / (y1 - y0);
  remap[3][0] = -(x1 + x0) / (x1 - x0);
  remap[3][1] = -(y1 + y0) / (y1 - y0);
  return remap * full;
}

void hash_camera(Hasher& h, const Camera& c) {
  h.value(c.projection);
  h.value(c.position);
  h.value(c.target);
  h.value(c.up);
  h.value(c.fov_y_degrees);
  h.value(c.view_height);
  h.value(c.near_plane);
  h.value(c.far_plane);
}

Camera CameraPath::at(const Camera& base, int frame) const {
  Camera cam = base;
  const float t = frames > 1 ? static_cast<float>(std::clamp(frame, 0, frames - 1)) /
                                   static_cast<float>(frames - 1)
                             : 0.0f;
  switch (type) {
    case CameraPathType::Static:
      break;
    case CameraPathType::Orbit: {
      const float angle = glm::radians(orbit_degrees) * t;
      cam.position = base.target + glm::rotate(base.position - base.target, angle, glm::normalize(orbit_axis));
      break;
    }
    case CameraPathType::Dolly:
      cam.position = glm::mix(base.position, dolly_to, t);
      break;
    case CameraPathType::Keyframes: {
      if (keys.empty()) break;
      if (keys.size() == 1) {
        cam.position = keys[0].position;
        cam.target = keys[0].target;
        break;
      }
      const float s = t * static_cast<float>(keys.size() - 1);
      const auto i = std::min(static_cast<std::size_t>(s), keys.size() - 2);
      const float u = s - static_cast<float>(i);
      cam.position = glm::mix(keys[i].position, keys[i + 1].position, u);
      cam.target = glm::mix(keys[i].target, keys[i + 1].target, u);
      break;
    }
  }
  return cam;
}

}  // namespace glintlab
