#include "path/camera_rays.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace glintlab {

CameraRays::CameraRays(const Camera& camera, glm::ivec2 film)
    : clip_to_world_(glm::inverse(
          glm::dmat4(camera.projection_matrix(static_cast<float>(film.x) / static_cast<float>(film.y))) *
          glm::dmat4(camera.view_matrix()))),
      film_(film), eye_(camera.position), orthographic_(camera.projection == Projection::Orthographic) {}

glm::dvec3 CameraRays::unproject(glm::dvec2 ndc, double z) const {
  const glm::dvec4 p = clip_to_world_ * glm::dvec4(ndc, z, 1.0);
  return glm::dvec3(p) / p.w;
}

RayDifferential CameraRays::at(glm::vec2 pixel) const {
  const glm::dvec2 ndc(-1.0 + 2.0 * pixel.x / film_.x, 1.0 - 2.0 * pixel.y / film_.y);
  const glm::dvec2 step_x(2.0 / film_.x, 0.0), step_y(0.0, -2.0 / film_.y);  // one pixel, in NDC
  // On a plane of constant NDC depth the clip w is constant (perspective and orthographic alike),
  // so the near and far points are affine in the film point: one pixel's difference is their
  // exact derivative.
  const glm::dvec3 near = unproject(ndc, -1.0), far = unproject(ndc, 1.0);
  const glm::dvec3 dNearDx = unproject(ndc + step_x, -1.0) - near, dNearDy = unproject(ndc + step_y, -1.0) - near;
  const glm::dvec3 dFarDx = unproject(ndc + step_x, 1.0) - far, dFarDy = unproject(ndc + step_y, 1.0) - far;

  const glm::dvec3 d = far - near;
  const double length = glm::length(d);
  const glm::dvec3 direction = d / length;
  // The derivative of d / |d| (Igehy 1999, eq. 7): the part of d' across the direction, over |d|.
  auto unit_derivative = [&](glm::dvec3 dd) { return (dd - direction * glm::dot(direction, dd)) / length; };
  return RayDifferential{.origin = glm::vec3(near),
                         .direction = glm::vec3(direction),
                         .dOdx = glm::vec3(dNearDx),
                         .dOdy = glm::vec3(dNearDy),
                         .dDdx = glm::vec3(unit_derivative(dFarDx - dNearDx)),
                         .dDdy = glm::vec3(unit_derivative(dFarDy - dNearDy))};
}

RayDifferential CameraRays::towards(glm::vec3 p) const {
  RayDifferential r = at(glm::vec2(film_ * 0.5));
  if (orthographic_) {
    r.origin = p - r.direction * glm::dot(p - r.origin, r.direction);
    return r;
  }
  // The rotation taking the centre's direction to p's (Rodrigues), applied to its differentials;
  // from the eye, whose rays do not move (dO = 0).
  const glm::vec3 to = glm::normalize(p - eye_), axis = glm::cross(r.direction, to);
  const float c = glm::dot(r.direction, to), s = glm::length(axis);
  auto turn = [&](glm::vec3 v) {
    if (s < 1e-7f) return c > 0.0f ? v : -v;
    const glm::vec3 k = axis / s;
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0f - c);
  };
  return RayDifferential{.origin = eye_, .direction = to, .dOdx = glm::vec3(0.0f), .dOdy = glm::vec3(0.0f),
                         .dDdx = turn(r.dDdx), .dDdy = turn(r.dDdy)};
}

}  // namespace glintlab
