#include "prefilter/position_normal_elements.hpp"

#include <bit>

#include "core/error.hpp"

namespace glintlab {

PositionNormalElementBuffers pack_position_normal_elements(std::span<const PositionNormalDistribution* const> per_material,
                                                           int max_materials) {
  static_assert(sizeof(PositionNormalDistribution::Element) == 6 * sizeof(float));
  PositionNormalElementBuffers out;
  out.normals.assign(static_cast<std::size_t>(max_materials + (max_materials & 1)), kNoStoredElements);
  std::size_t elements = 0;
  for (std::size_t m = 0; m < per_material.size() && m < static_cast<std::size_t>(max_materials); ++m) {
    const PositionNormalDistribution* d = per_material[m];
    if (!d) continue;
    if (elements + d->elements().size() >= kNoStoredElements)
      throw RuntimeFailure("normal-map elements exceed 2^32 on the GPU");
    out.normals[m] = static_cast<std::uint32_t>(elements);
    for (const PositionNormalDistribution::Element& e : d->elements()) {
      out.normals.insert(out.normals.end(), {std::bit_cast<std::uint32_t>(e.projected.x),
                                             std::bit_cast<std::uint32_t>(e.projected.y)});
      out.jacobians.insert(out.jacobians.end(), {e.jacobian[0][0], e.jacobian[0][1], e.jacobian[1][0], e.jacobian[1][1]});
    }
    elements += d->elements().size();
  }
  return out;
}

std::uint64_t position_normal_element_bytes(int width, int height, int k) {
  return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * static_cast<std::uint64_t>(k * k) *
         6 * sizeof(float);
}

}  // namespace glintlab
