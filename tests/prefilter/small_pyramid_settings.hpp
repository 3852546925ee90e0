#pragma once
// The prefilter tests' small pyramid: 32^2 NDF pixels in 8^2 blocks, a footprint a texel apart at
// the first level, rank 16 (fast to precompute on maps of a few dozen texels).
#include "prefilter/prefiltered_ndf.hpp"

namespace glintlab::test {

inline PrefilterSettings small_pyramid_settings() {
  PrefilterSettings s;
  s.ndf_resolution = 32;
  s.block_size = 8;
  s.base_stride = 1;
  s.group_footprints = 4;
  s.cp.rank = 16;
  return s;
}

}  // namespace glintlab::test
