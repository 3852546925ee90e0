#pragma once
// The reference's pixel filter: how the sub-pixel samples of a pass become a pixel. `box` averages
// the k x k samples inside the pixel; `gaussian` (S = kPixelFilterSigma, the methods' pixel filter:
// src/core/pixel_filter_width.hpp) or `gaussian:S` weights every sample within 3 S pixels of the
// pixel's centre (per axis) by a Gaussian of standard deviation S pixels, normalised per pixel over
// the samples that exist, so that a reference can share a method's Gaussian footprint model
// (docs/methods.md, "Ground truth", "Pixel filter").
#include <string>

namespace glintlab {

struct PixelFilter {
  enum class Kind { box, gaussian };
  static constexpr float kMinSigma = 0.1f;  ///< pixels; below, a k <= 32 grid cannot resolve it
  static constexpr float kMaxSigma = 4.0f;  ///< pixels; beyond, a footprint of 25^2 pixels
  static constexpr float kTruncation = 3.0f;  ///< in standard deviations, per axis

  Kind kind = Kind::box;
  float sigma = 0.0f;  ///< pixels; gaussian only

  /// "box", "gaussian" (S = kPixelFilterSigma) or "gaussian:S" with S in kMinSigma .. kMaxSigma;
  /// throws InputError naming --reference-filter, the value and what is allowed.
  static PixelFilter parse(const std::string& text);
  static PixelFilter gaussian(float sigma_pixels) { return {Kind::gaussian, sigma_pixels}; }

  [[nodiscard]] bool is_box() const { return kind == Kind::box; }
  /// The text parse() takes back: "box" or "gaussian:S" (S in shortest round-trip form).
  [[nodiscard]] std::string text() const;
  /// Whole pixels on each side of a pixel whose samples it can weight: 0 for the box,
  /// ceil(kTruncation sigma) for the Gaussian (a sample of the pixel R + 1 away is at least
  /// R + 0.5 pixels from the centre).
  [[nodiscard]] int support_pixels() const;

  bool operator==(const PixelFilter&) const = default;
};

}  // namespace glintlab
