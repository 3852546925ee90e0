#include "render/pixel_filter.hpp"

#include <charconv>
#include <cmath>

#include "core/error.hpp"
#include "core/pixel_filter_width.hpp"

namespace glintlab {

namespace {

std::string allowed() {
  return "allowed: box, gaussian (S = " + pixel_filter_sigma_text() +
         ", the methods' pixel filter) or gaussian:S with S the standard deviation in pixels, 0.1 .. 4";
}

}  // namespace

PixelFilter PixelFilter::parse(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return InputError("--reference-filter " + text + ": " + why + "; " + allowed());
  };
  if (text == "box") return {};
  if (text == "gaussian") return gaussian(kPixelFilterSigma);
  const std::string prefix = "gaussian:";
  if (text.rfind(prefix, 0) != 0) throw bad("unknown filter");
  const std::string number = text.substr(prefix.size());
  float sigma = 0.0f;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), sigma);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size() || !std::isfinite(sigma))
    throw bad("'" + number + "' is not a number");
  if (sigma < kMinSigma || sigma > kMaxSigma) throw bad("sigma " + number + " out of range");
  return gaussian(sigma);
}

std::string PixelFilter::text() const { return is_box() ? "box" : "gaussian:" + shortest_text(sigma); }

int PixelFilter::support_pixels() const {
  return is_box() ? 0 : static_cast<int>(std::ceil(kTruncation * sigma));
}

}  // namespace glintlab
