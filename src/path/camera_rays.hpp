#pragma once
// Camera rays with their differentials (Igehy 1999, "Tracing ray differentials", sec. 3): the ray
// through a point of the film, and how its origin and direction change per pixel in x and y, from
// which a hit point's footprint follows. The camera is the raster passes' own (Camera's view and
// projection matrices), so both backends see the same film; a ray starts on the near plane, where
// the rasteriser clips.
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/camera.hpp"

namespace glintlab {

/// A ray and its derivatives per pixel of the film: origin O, unit direction D.
struct RayDifferential {
  glm::vec3 origin;
  glm::vec3 direction;
  glm::vec3 dOdx, dOdy;  ///< per pixel right, per pixel down
  glm::vec3 dDdx, dDdy;
};

class CameraRays {
 public:
  /// Rays of `camera` over a film of `film` pixels (the aspect the raster passes use).
  CameraRays(const Camera& camera, glm::ivec2 film);

  /// The ray through the film point `pixel`, in pixels from the film's top-left corner (y down):
  /// the centre of pixel (i, j) is (i + 0.5, j + 0.5).
  [[nodiscard]] RayDifferential at(glm::vec2 pixel) const;
  /// A ray through the world point p with the differentials of the film centre's ray, turned (or,
  /// orthographic, moved) to pass through p: the footprint a camera would give a point it does not
  /// see directly (pbrt-v4's Camera::Approximate_dp_dxy), for path vertices after a bounce.
  [[nodiscard]] RayDifferential towards(glm::vec3 p) const;

 private:
  /// The world point at normalised device coordinates (x, y) and depth z (-1 near, 1 far).
  [[nodiscard]] glm::dvec3 unproject(glm::dvec2 ndc, double z) const;

  glm::dmat4 clip_to_world_;  // in double: the far plane is thousands of near planes away
  glm::dvec2 film_;
  glm::vec3 eye_;
  bool orthographic_;
};

}  // namespace glintlab
