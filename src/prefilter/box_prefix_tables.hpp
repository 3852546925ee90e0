#pragma once
// Constant-cost box queries of Deng et al. 2022's pyramid (issue 30, item 7). The paper's box query
// (sec. 4.4, eq. 7) sums, per angular block the box overlaps, R products of the factors' prefix
// sums: its cost grows with the box, up to (N/B)^2 blocks. These tables add per footprint 2D
// prefix sums over its block grid, so that the integral of the reconstructed image over [0, x] x
// [0, y] is, with (bx, by) the block holding (x, y) and (x', y') the position inside it,
//   F(x, y) = Q + sum_r [ SA_r(x') (SB_r(y') c_r + U_r) + SB_r(y') L_r ]
// Q: the blocks wholly below and left; U_r: rank r over the blocks below in the column (their b
// totals times c); L_r: over the blocks left in the row (a totals times c). Any box is then its four
// corners, O(R) each whatever its size. Derived from the pyramid when it is packed (not cached):
// 2R + 1 floats per block of every footprint.
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "prefilter/prefiltered_ndf.hpp"

namespace glintlab {

struct BoxPrefixTables {
  int block_stride = 0;  ///< floats per block: Q, then U_0 .. U_{R-1}, then L_0 .. L_{R-1}
  int footprint_stride = 0;  ///< floats per footprint: (N/B)^2 blocks in bit order (by * (N/B) + bx)
  std::vector<float> values;

  [[nodiscard]] const float* block(std::uint32_t footprint, int bit) const {
    return &values[static_cast<std::size_t>(footprint) * static_cast<std::size_t>(footprint_stride) +
                   static_cast<std::size_t>(bit * block_stride)];
  }
};

[[nodiscard]] BoxPrefixTables box_prefix_tables(const PrefilteredNdf& pyramid);

/// The tables' size in bytes without building them: (N/B)^2 (2R + 1) floats per footprint.
[[nodiscard]] inline std::size_t box_prefix_tables_bytes(const PrefilteredNdf& pyramid) {
  const auto blocks = static_cast<std::size_t>(pyramid.blocks_per_side() * pyramid.blocks_per_side());
  return pyramid.footprints.size() * blocks * static_cast<std::size_t>(2 * pyramid.rank() + 1) * sizeof(float);
}

/// PrefilteredNdf::pixel_range_sum through the tables: the integral of footprint f's pixels over
/// [x0, x1] (continuous pixel coordinates in [0, N]) from its four corners, the differences of
/// table entries taken first so that a box inside one block row or column cancels exactly. The
/// GPU's query (shaders/glints/normal-map/prefiltered_ndf.glsl) is its twin.
[[nodiscard]] double box_prefix_range_sum(const PrefilteredNdf& pyramid, const BoxPrefixTables& tables,
                                          std::uint32_t footprint, glm::dvec2 x0, glm::dvec2 x1);

}  // namespace glintlab
