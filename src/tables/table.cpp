#include "tables/table.hpp"

namespace glintlab {

TableBytes mip_chain_bytes_1d(int texels, int layers, std::size_t texel_bytes) {
  TableBytes bytes;
  bytes.base = static_cast<std::size_t>(texels) * static_cast<std::size_t>(layers) * texel_bytes;
  for (int width = texels; width >= 1; width /= 2)
    bytes.with_mips += static_cast<std::size_t>(width) * static_cast<std::size_t>(layers) * texel_bytes;
  return bytes;
}

}  // namespace glintlab
