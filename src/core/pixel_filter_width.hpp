#pragma once
// The one pixel-filter width: the standard deviation of the Gaussian pixel filter that the methods'
// footprint models assume and that the reference's `--reference-filter gaussian` applies, so that
// a method and its ground truth answer the same question (docs/methods.md, "Pixel footprint").
// Kaplanyan et al. 2016's talk filters with "a standard deviation of 0.5 pixel"; Tokuyoshi &
// Kaplanyan 2019's sigma2 = 0.25 is its square. The GLSL sees it as PIXEL_FILTER_SIGMA
// (src/render/shader_contract.cpp); kaplanyan-beckmann uses it, tokuyoshi's `sigma2` and the
// `footprint_sigma` of yan2016 and deng2022 default to it.
#include <charconv>
#include <string>

namespace glintlab {

inline constexpr float kPixelFilterSigma = 0.5f;  ///< pixels

/// A float in shortest round-trip form ("0.5", "0.25").
inline std::string shortest_text(float value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

/// kPixelFilterSigma and its square as text, for the descriptions and messages that state them.
inline std::string pixel_filter_sigma_text() { return shortest_text(kPixelFilterSigma); }
inline std::string pixel_filter_variance_text() { return shortest_text(kPixelFilterSigma * kPixelFilterSigma); }

}  // namespace glintlab
