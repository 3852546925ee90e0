#include "core/colour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

#include "core/star_bloom.hpp"

namespace glintlab {

float aces_filmic(float x) {
  // Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit of the ACES RRT+ODT.
  constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  x = std::max(x, 0.0f);
  return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

float srgb_encode(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

Image tonemap_for_display(const Image& linear, float exposure_stops, float bloom) {
  const float gain = std::exp2(exposure_stops);
  Image exposed(linear.width(), linear.height());
  for (std::size_t i = 0; i < linear.pixel_count(); ++i) exposed.pixels()[i] = gain * linear.pixels()[i];
  // Streaks of about 1.5% of the picture's height, whatever its resolution.
  if (bloom > 0.0f) exposed = star_bloom(exposed, bloom, 0.015f * static_cast<float>(linear.height()));
  Image out(linear.width(), linear.height());
  for (std::size_t i = 0; i < linear.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) out.pixels()[i][c] = srgb_encode(aces_filmic(exposed.pixels()[i][c]));
  return out;
}

Image false_colour(const Image& error, float scale) {
  // Magma-like ramp: black -> purple -> orange -> pale yellow (sRGB control points).
  static constexpr std::array<glm::vec3, 5> ramp = {
      glm::vec3(0.0f, 0.0f, 0.02f), glm::vec3(0.31f, 0.07f, 0.48f), glm::vec3(0.72f, 0.21f, 0.47f),
      glm::vec3(0.98f, 0.53f, 0.38f), glm::vec3(0.99f, 0.99f, 0.75f)};
  Image out(error.width(), error.height());
  const float inv = scale > 0.0f ? 1.0f / scale : 0.0f;
  for (std::size_t i = 0; i < error.pixel_count(); ++i) {
    const float t = std::clamp(error.pixels()[i].r * inv, 0.0f, 1.0f) * (ramp.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(t), ramp.size() - 2);
    out.pixels()[i] = glm::mix(ramp[k], ramp[k + 1], t - static_cast<float>(k));
  }
  return out;
}

}  // namespace glintlab
