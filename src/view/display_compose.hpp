#pragma once
// What the viewer shows, assembled on the CPU from display-encoded images (tonemap_for_display's,
// the PNGs' transform): a split between two images, the false-colour error map over an image,
// and the 8-bit RGBA the window's texture holds (quantised as write_png does).
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace glintlab {

/// Columns left of `split` x width from `left`, the rest from `right` (same sizes).
Image split_images(const Image& left, const Image& right, float split);

/// `base` with `overlay` blended over it at `opacity` (0: base, 1: overlay).
Image blend_images(const Image& base, const Image& overlay, float opacity);

/// compare's error map of `method` against `reference` (linear radiance): |luminance
/// difference| in false colour, scaled so its kErrorMapPercentile is the top of the ramp.
Image error_map_display(const Image& method, const Image& reference);

/// RGBA8, row 0 at the top, each channel unorm8(v) as in the PNGs.
std::vector<std::uint8_t> to_rgba8(const Image& display);

}  // namespace glintlab
