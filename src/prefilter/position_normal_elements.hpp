#pragma once
// The elements of Yan et al. 2016's position-normal distributions (position_normal.hpp), p_e and
// J_e of k x k per texel, precomputed once per map and packed into the two storage buffers that
// shaders/glints/normal-map/position_normal.glsl reads where a method defines
// POSITION_NORMAL_STORED_ELEMENTS (yan2016, deng2022's fallback). Built from the map, they spare
// every element of every light's sum its 5 texel reads and 5 normalisations (k = 1; 4 reads and 5
// bilinear normals at k = 2): an element is one vec2 and one vec4 load.
//
// normals: word m (m < max_materials) is material m's first element, or kNoStoredElements; then
//   the elements' p_e, two floats each (std430 vec2s: the words before them are even in number).
// jacobians: J_e per element, four floats (column-major: dp/du.x, then dp/du.y).
// Material m's element (ex, ey) is at first + ey (k width) + ex, row major as the CPU's.
#include <cstdint>
#include <span>
#include <vector>

#include "prefilter/position_normal.hpp"

namespace glintlab {

inline constexpr std::uint32_t kNoStoredElements = 0xffffffffu;

struct PositionNormalElementBuffers {
  std::vector<std::uint32_t> normals;  ///< the materials' first elements, then their p_e as float bits
  std::vector<float> jacobians;
};

/// `per_material[m]`: material m's distribution (its elements), or null. Throws RuntimeFailure
/// past 2^32 elements.
PositionNormalElementBuffers pack_position_normal_elements(std::span<const PositionNormalDistribution* const> per_material,
                                                           int max_materials);

/// Bytes of the packed elements of a width x height map at k elements per texel and axis.
std::uint64_t position_normal_element_bytes(int width, int height, int k);

}  // namespace glintlab
