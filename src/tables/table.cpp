#include "tables/table.hpp"

#include <cstdio>

namespace glintlab {

std::string TableConstant::glsl_value() const {
  if (integer) return std::to_string(static_cast<long long>(value));
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(static_cast<float>(value)));  // round-trips a float
  std::string out = text;
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out;
}

TableBytes mip_chain_bytes_1d(int texels, int layers, std::size_t texel_bytes) {
  TableBytes bytes;
  bytes.base = static_cast<std::size_t>(texels) * static_cast<std::size_t>(layers) * texel_bytes;
  for (int width = texels; width >= 1; width /= 2)
    bytes.with_mips += static_cast<std::size_t>(width) * static_cast<std::size_t>(layers) * texel_bytes;
  return bytes;
}

}  // namespace glintlab
