#include "scene/lights/environment_glint_levels.hpp"

#include <algorithm>
#include <cmath>

namespace glintlab {

std::array<float, kEnvironmentGlintLevels> environment_glint_tent_weights(
    float y, const std::array<float, kEnvironmentGlintLevels>& levels) {
  std::array<float, kEnvironmentGlintLevels> w{};
  if (!(y > 0.0f)) {
    w[0] = 1.0f;
    return w;
  }
  for (int k = 0; k + 1 < kEnvironmentGlintLevels; ++k) {
    const float lo = levels[static_cast<std::size_t>(k)], hi = levels[static_cast<std::size_t>(k) + 1];
    if (y <= hi && hi > lo) {
      const float a = (y - lo) / (hi - lo);  // linear in y: sum_k L_k w_k = y
      w[static_cast<std::size_t>(k)] = 1.0f - a;
      w[static_cast<std::size_t>(k) + 1] = a;
      return w;
    }
  }
  w.back() = 1.0f;  // at (or, by rounding, above) the brightest level
  return w;
}

std::array<float, kEnvironmentGlintLevels> environment_glint_luminance_levels(const Image& radiance) {
  std::array<float, kEnvironmentGlintLevels> levels{};
  float brightest = 0.0f;
  for (const glm::vec3& p : radiance.pixels()) brightest = std::max(brightest, luminance(p));
  if (brightest <= 0.0f) return levels;  // black (or empty): every texel is level 0
  const float black = kEnvironmentGlintBlackLevel * brightest;
  float dimmest = brightest;
  for (const glm::vec3& p : radiance.pixels())
    if (const float y = luminance(p); y > black) dimmest = std::min(dimmest, y);
  // L_i = exp(lerp(ln Y_min, ln Y_max, i / 3)) for i = 1, 2, 3: Y_min itself is not a level.
  for (int i = 1; i < kEnvironmentGlintLevels; ++i) {
    const double t = double(i) / (kEnvironmentGlintLevels - 1);
    levels[static_cast<std::size_t>(i)] =
        static_cast<float>(std::exp((1.0 - t) * std::log(double(dimmest)) + t * std::log(double(brightest))));
  }
  levels.back() = brightest;  // exactly
  return levels;
}

EnvironmentGlintLevels environment_glint_levels(const Image& radiance) {
  EnvironmentGlintLevels out;
  if (radiance.empty()) return out;
  out.luminance = environment_glint_luminance_levels(radiance);
  out.weights = Image(radiance.width(), radiance.height());
  for (std::size_t i = 0; i < radiance.pixel_count(); ++i) {
    const auto w = environment_glint_tent_weights(luminance(radiance.pixels()[i]), out.luminance);
    out.weights.pixels()[i] = glm::vec3(w[1], w[2], w[3]);
  }
  return out;
}

}  // namespace glintlab
