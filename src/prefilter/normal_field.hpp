#pragma once
// The surface a normal-map-glints material describes (docs/methods.md#yan2016): the normal field
// n(u) = normalize(bilinear interpolation of the texel normals), exactly what GL_LINEAR at mip level 0
// with GL_REPEAT returns, and its projected normal p(u) = n(u).xy. Positions u are in texels of the
// map: texel (i, j) covers [i, i + 1) x [j, j + 1), its normal sits at its centre, and the map wraps.
#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// Index i of a map n texels wide that wraps (GL_REPEAT), in [0, n).
inline int wrap_texel(int i, int n) { return i >= 0 && i < n ? i : ((i % n) + n) % n; }

class NormalField {
 public:
  explicit NormalField(const NormalMap& map) : map_(&map) {}

  [[nodiscard]] int width() const { return map_->width; }
  [[nodiscard]] int height() const { return map_->height; }
  /// The texel normal at integer indices, wrapped.
  [[nodiscard]] glm::dvec3 texel(int x, int y) const;
  /// n(u), unit length.
  [[nodiscard]] glm::dvec3 normal(glm::dvec2 u) const;
  [[nodiscard]] glm::dvec2 projected(glm::dvec2 u) const { return glm::dvec2(normal(u)); }
  /// dp/du by central differences of step `delta` texels (columns: d/du.x, d/du.y).
  [[nodiscard]] glm::dmat2 projected_jacobian(glm::dvec2 u, double delta) const;

 private:
  const NormalMap* map_;
};

}  // namespace glintlab
