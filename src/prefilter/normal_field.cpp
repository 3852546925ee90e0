#include "prefilter/normal_field.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace glintlab {

glm::dvec3 NormalField::texel(int x, int y) const {
  const auto i = static_cast<std::size_t>(wrap_texel(y, map_->height)) * static_cast<std::size_t>(map_->width) +
                 static_cast<std::size_t>(wrap_texel(x, map_->width));
  return glm::dvec3(map_->normals[i]);
}

glm::dvec3 NormalField::normal(glm::dvec2 u) const {
  // GL_LINEAR: the four texels whose centres surround u, weighted by u's offset from the first.
  const glm::dvec2 q = u - 0.5;
  const glm::dvec2 f0 = glm::floor(q);
  const glm::dvec2 f = q - f0;
  const int x = static_cast<int>(f0.x), y = static_cast<int>(f0.y);
  const glm::dvec3 n = (1 - f.y) * ((1 - f.x) * texel(x, y) + f.x * texel(x + 1, y)) +
                       f.y * ((1 - f.x) * texel(x, y + 1) + f.x * texel(x + 1, y + 1));
  const double len = glm::length(n);
  return len > 0 ? n / len : glm::dvec3(0, 0, 1);
}

glm::dmat2 NormalField::projected_jacobian(glm::dvec2 u, double delta) const {
  const glm::dvec2 dx = (projected(u + glm::dvec2(delta, 0)) - projected(u - glm::dvec2(delta, 0))) / (2 * delta);
  const glm::dvec2 dy = (projected(u + glm::dvec2(0, delta)) - projected(u - glm::dvec2(0, delta))) / (2 * delta);
  return glm::dmat2(dx, dy);
}

}  // namespace glintlab
