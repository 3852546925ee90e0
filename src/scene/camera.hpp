#pragma once
// Pinhole perspective or orthographic camera, and camera paths for motion over N frames.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace glintlab {

enum class Projection { Perspective, Orthographic };

struct Camera {
  Projection projection = Projection::Perspective;
  glm::vec3 position{0.0f, 1.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 40.0f;  ///< perspective: full vertical field of view
  float view_height = 2.0f;     ///< orthographic: world-space height of the view
  float near_plane = 0.05f;
  float far_plane = 200.0f;

  [[nodiscard]] glm::mat4 view_matrix() const;
  /// Projection of the whole film with the given aspect (width / height).
  [[nodiscard]] glm::mat4 projection_matrix(float aspect) const;
  /// Projection of the sub-rectangle [x0,x1) x [y0,y1) of a film of size `film` (pixels, y down):
  /// the full projection followed by a window-to-tile remap, so tiles stitch exactly.
  [[nodiscard]] glm::mat4 tile_projection_matrix(glm::ivec2 film, glm::ivec2 origin, glm::ivec2 size) const;
};

class Hasher;
/// Feeds every field that affects an image into a hash.
void hash_camera(Hasher& h, const Camera& c);

struct CameraKey {
  glm::vec3 position;
  glm::vec3 target;
};

enum class CameraPathType { Static, Orbit, Dolly, Keyframes };

/// Moves the camera over `frames` frames; frame 0 is the scene's camera for orbit and dolly.
struct CameraPath {
  CameraPathType type = CameraPathType::Static;
  int frames = 1;
  float orbit_degrees = 0.0f;        ///< orbit: total rotation about `orbit_axis` through the target
  glm::vec3 orbit_axis{0, 1, 0};
  glm::vec3 dolly_to{0.0f};          ///< dolly: position at the last frame (target fixed)
  std::vector<CameraKey> keys;       ///< keyframes: evenly spaced over the frames, linear in between

  [[nodiscard]] Camera at(const Camera& base, int frame) const;
};

}  // namespace glintlab
