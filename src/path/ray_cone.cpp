#include "path/ray_cone.hpp"

#include <algorithm>
#include <cmath>

namespace glintlab {

float lobe_spread(float alpha, bool diffuse) {
  return diffuse ? 0.5f : std::min(0.5f, std::sqrt(2.0f) * std::max(alpha, 0.0f));
}

std::pair<glm::vec3, glm::vec3> widen_footprint(glm::vec3 dPdx, glm::vec3 dPdy, glm::vec3 direction, glm::vec3 normal,
                                                float width, float sigma) {
  const float dn = glm::dot(direction, normal);
  if (!(width > 0.0f) || std::abs(dn) < 1e-6f) return {dPdx, dPdy};
  // A basis of the plane across the ray, and one of the surface's plane.
  auto across = [](glm::vec3 axis) {
    return glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  };
  const glm::vec3 e1 = across(direction), e2 = glm::cross(direction, e1);
  const glm::vec3 u = across(normal), v = glm::cross(normal, u);
  // The cross-section's axes moved along the ray onto the surface: e - D (e.n) / (D.n).
  const float scale = width / sigma;
  const glm::vec3 c1 = scale * (e1 - direction * (glm::dot(e1, normal) / dn));
  const glm::vec3 c2 = scale * (e2 - direction * (glm::dot(e2, normal) / dn));
  // The covariance of the four steps in the surface's (u, v) basis.
  float a = 0, b = 0, c = 0;
  for (const glm::vec3& s : {dPdx, dPdy, c1, c2}) {
    const float x = glm::dot(s, u), y = glm::dot(s, v);
    a += x * x, b += x * y, c += y * y;
  }
  // Its principal axes: eigenvalues of [[a, b], [b, c]], and unit eigenvectors.
  const float mean = 0.5f * (a + c), radius = std::sqrt(0.25f * (a - c) * (a - c) + b * b);
  const float major = mean + radius, minor = std::max(mean - radius, 0.0f);
  const float angle = 0.5f * std::atan2(2.0f * b, a - c);
  const glm::vec3 first = std::cos(angle) * u + std::sin(angle) * v, second = glm::cross(normal, first);
  return {std::sqrt(major) * first, std::sqrt(minor) * second};
}

}  // namespace glintlab
