#pragma once
// Display transforms. Metrics are never computed on these: they act on linear radiance only.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/image.hpp"

namespace glintlab {

/// Exposure (in stops), an optional star bloom (core/star_bloom.hpp; 0: none), ACES filmic
/// tonemap (Narkowicz 2015 fit), then sRGB encoding. The fit keeps highlights' hue and rolls off
/// smoothly, which matters for tiny bright glints.
Image tonemap_for_display(const Image& linear, float exposure_stops, float bloom = 0.0f);

float aces_filmic(float x);
float srgb_encode(float linear);
/// The inverse of srgb_encode (IEC 61966-2-1): a display-encoded value as the light it shows.
float srgb_decode(float encoded);

/// An 8-bit value of a display-encoded one in [0, 1] (clamped, rounded): what the PNGs, the
/// viewer's texture and the glTF textures glintlab writes hold.
inline std::uint8_t unorm8(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

/// False-colour map of |error| scaled so that `scale` maps to the top of the colour ramp.
Image false_colour(const Image& error_magnitude, float scale);

}  // namespace glintlab
