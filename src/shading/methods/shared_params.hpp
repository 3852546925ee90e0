#pragma once
// Parameters that several methods declare with the same meaning.
#include "shading/method.hpp"

namespace glintlab {

/// Lobes narrower than this see lights with extent as a mirror would (docs/methods.md#conventional).
inline ParamDecl mirror_alpha_param() {
  return {"mirror_alpha", 0.01f, 0.0f, 1.0f,
          "lobes narrower than this (alpha units) see lights with extent as a mirror would"};
}

/// Upper clamp of the slope-space footprint (Kaplanyan et al. 2016's fp_max).
inline ParamDecl fp_max_param() {
  return {"fp_max", 1.0f, 0.01f, 4.0f,
          "upper clamp of the footprint's half extent in slope space (the talk uses 0.1 .. 1)"};
}

}  // namespace glintlab
