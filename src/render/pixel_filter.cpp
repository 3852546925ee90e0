#include "render/pixel_filter.hpp"

#include <charconv>
#include <cmath>

#include "core/error.hpp"

namespace glintlab {

namespace {

constexpr const char* kAllowed = "allowed: box, or gaussian:S with S the standard deviation in pixels, 0.1 .. 4";

std::string shortest(float v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

}  // namespace

PixelFilter PixelFilter::parse(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return InputError("--reference-filter " + text + ": " + why + "; " + kAllowed);
  };
  if (text == "box") return {};
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

std::string PixelFilter::text() const { return is_box() ? "box" : "gaussian:" + shortest(sigma); }

int PixelFilter::support_pixels() const {
  return is_box() ? 0 : static_cast<int>(std::ceil(kTruncation * sigma));
}

}  // namespace glintlab
