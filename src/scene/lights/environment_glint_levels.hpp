#pragma once
// An environment map (environment_map.hpp's convention) partitioned into regions of luminance for
// glints under image-based lighting (Kneiphof & Klein 2025, "Real-time Image-based Lighting of
// Glints", CGF 44(4)): levels L_0 = 0 < L_1 <= L_2 <= L_3 = Y_max, log-spaced from the dimmest
// luminance above a black level to the brightest, and per texel the tent weights w_k of the two
// levels around its luminance Y (a partition of unity with sum_k L_k w_k = Y exactly). Each
// region's weight map, prefiltered by the same GGX chain as the radiance
// (environment_prefilter.hpp), is the share of a lobe's reflected directions that fall in the
// region; a facet count split among the regions by those shares, each region lit by its level,
// gives the glints' brightness under the environment (the method `kneiphof2025`).
// Because the filter is linear and the same, sum_k L_k w_k stays the luminance of the prefiltered
// radiance at every texel of every level: the glints' mean is the split sum's.
#include <array>
#include <vector>

#include "core/image.hpp"

namespace glintlab {

inline constexpr int kEnvironmentGlintLevels = 4;  ///< L_0 = 0 and three log-spaced levels
/// The black level, relative to the brightest luminance: texels dimmer than it count as black
/// when the dimmest level is chosen (their light still enters the tent weights).
inline constexpr float kEnvironmentGlintBlackLevel = 1e-4f;

struct EnvironmentGlintLevels {
  std::array<float, kEnvironmentGlintLevels> luminance{};  ///< L_0 = 0 < L_1 <= L_2 <= L_3
  Image weights;  ///< per texel, w_1, w_2, w_3 in RGB (w_0 = 1 - their sum)
};

/// The levels and weights of a radiance map (an empty map gives all levels 0 and no weights).
EnvironmentGlintLevels environment_glint_levels(const Image& radiance);
/// The levels alone (what the environment light's GPU record carries; all 0 for a black map).
std::array<float, kEnvironmentGlintLevels> environment_glint_luminance_levels(const Image& radiance);

/// The tent weights of luminance y between the levels (w_0 .. w_3).
std::array<float, kEnvironmentGlintLevels> environment_glint_tent_weights(
    float y, const std::array<float, kEnvironmentGlintLevels>& levels);

}  // namespace glintlab
