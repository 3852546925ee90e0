#include "core/star_bloom.hpp"

#include <array>
#include <cmath>

namespace glintlab {

Image star_bloom(const Image& linear, float strength, float length) {
  const int w = linear.width(), h = linear.height();
  Image bright(w, h), out = linear;
  for (std::size_t i = 0; i < linear.pixel_count(); ++i) bright.pixels()[i] = glm::max(linear.pixels()[i] - 1.0f, 0.0f);

  const float decay = std::exp(-1.0f / std::max(length, 1e-3f));
  const float weight = strength * (1.0f - decay) / (8.0f * decay);  // sum over one ray of decay^k, k >= 1
  static constexpr std::array<glm::ivec2, 8> kRays = {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1),
                                                      glm::ivec2(0, -1), glm::ivec2(1, 1), glm::ivec2(-1, -1),
                                                      glm::ivec2(1, -1), glm::ivec2(-1, 1)};
  Image streak(w, h);
  for (const glm::ivec2 d : kRays) {
    // A first-order recursive filter along the ray: s(p) = decay (s(p - d) + bright(p - d)),
    // visiting p - d before p.
    const int x0 = d.x >= 0 ? 0 : w - 1, x1 = d.x >= 0 ? w : -1, sx = d.x >= 0 ? 1 : -1;
    const int y0 = d.y >= 0 ? 0 : h - 1, y1 = d.y >= 0 ? h : -1, sy = d.y >= 0 ? 1 : -1;
    for (int y = y0; y != y1; y += sy)
      for (int x = x0; x != x1; x += sx) {
        const int px = x - d.x, py = y - d.y;
        glm::vec3 s(0.0f);
        if (px >= 0 && px < w && py >= 0 && py < h) s = decay * (streak.at(px, py) + bright.at(px, py));
        streak.at(x, y) = s;
        out.at(x, y) += weight * s;
      }
  }
  return out;
}

}  // namespace glintlab
