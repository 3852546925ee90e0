#pragma once
// A star-shaped bloom for pictures of HDR glints, as Zirr & Kaplanyan 2016 and Chermain et al.
// 2020/2021 show them: what exceeds the display's white leaks along eight rays (four lines).
// Display only: metrics never see it (docs/scene-format.md, [film] bloom).
#include "core/image.hpp"

namespace glintlab {

/// linear + strength x streaks of max(linear - 1, 0), each ray an exponential decay of e-folding
/// length `length` pixels, the eight rays normalised so that they add `strength` times the
/// over-bright energy. Expects exposure already applied. Linear in, linear out.
Image star_bloom(const Image& linear, float strength, float length);

}  // namespace glintlab
