#pragma once
// The `scratches` generator's parts (generate_scratches in normal_map.hpp): straight segments, a
// Gaussian groove profile, and the periodic height they carve. Distances are in texels.
#include <glm/vec2.hpp>
#include <vector>

#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

struct Scratch {
  glm::vec2 from, to;  ///< end points, texels; the centre lies in the tile, the ends may not
};

/// depth (exp(-d^2 / (2 w^2)) - exp(-R^2 / (2 w^2))) for d < R = 4 w, else 0: a Gaussian of sigma
/// w cut where it is 3e-4 of its peak, shifted so the cut leaves no step in the height.
struct GrooveProfile {
  float width;   ///< w, texels
  float radius;  ///< R = 4 w
  float depth;   ///< texels; makes the largest central-difference slope across the groove `slope`
  [[nodiscard]] float operator()(float distance) const;
};

GrooveProfile groove_profile(float width, float slope);

/// The scratches in order: centre uniform in the tile, direction angle + spread (U - 1/2), length
/// length (0.5 + U) of the tile.
std::vector<Scratch> choose_scratches(const ScratchParams& params);

/// height(p) = -sum over the scratches and their periodic images of profile(distance from p to the
/// segment), at the texel centres (row 0 at v = 0). Each segment is rasterised only over the rows
/// it reaches and, per row, over the span within R of it; bands of rows run on every thread.
std::vector<float> scratch_heights(const ScratchParams& params, const std::vector<Scratch>& scratches,
                                   const GrooveProfile& profile);

}  // namespace glintlab
