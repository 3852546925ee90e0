#pragma once
// An environment map (environment_map.hpp's convention) prefiltered for the real-time methods'
// split-sum approximation (Karis 2013, "Real Shading in Unreal Engine 4", "Image-based lighting"): the
// specular integral of L(l) f(v, l) cos is split into the radiance convolved with the lobe,
// here (the first sum), times the lobe's directional albedo, the `dfg` table
// (src/tables/dfg_table.cpp, the second sum); and the diffuse term reads the irradiance map.
//
// Specular chain: kEnvironmentSpecularLevels lat-long maps, level 0 of width
// min(W, kEnvironmentSpecularBaseWidth), each next level half as wide and high but never below
// kEnvironmentSpecularMinWidth x kEnvironmentSpecularMinWidth/2 (or the map's own size, if
// smaller). Level m holds, at each texel centre's direction r, the radiance convolved with the
// GGX lobe of
// alpha_m = (m / (kEnvironmentSpecularLevels - 1))^2 under Karis's n = v = r assumption:
//     LD(r) = sum_k L(l_k) (n.l_k) / sum_k (n.l_k),  h_k ~ D(h) (n.h),  l_k = reflect(-r, h_k)
// (Karis 2013's PrefilterEnvMap listing); level 0 (alpha 0) is the downsampled radiance itself
// (downsample_environment). Each sample reads a box-filtered mip of the full-resolution map at
// the sample's solid-angle footprint (Krivanek & Colbert 2008, "Real-time Shading with Filtered
// Importance Sampling": lod = max(log4(Omega_s / Omega_p) + 1, 0)), so that small bright texels are integrated rather than aliased.
// A uniform map stays uniform at every level (the weights are normalised).
//
// Irradiance: a kEnvironmentIrradianceWidth x kEnvironmentIrradianceWidth/2 lat-long map of
// E(n) = integral L(l) max(0, n.l) d omega at each texel centre's direction, summed exactly over
// the map downsampled to at most kEnvironmentIrradianceSourceWidth columns: each source texel's
// integral of l d omega is closed-form, so a texel wholly above the horizon of n contributes
// L n.(integral of l d omega) exactly; texels the horizon crosses are split into
// kEnvironmentIrradianceSplit^2 parts. A uniform L gives pi L (to about 1e-5).
#include <vector>

#include "core/image.hpp"

namespace glintlab {

inline constexpr int kEnvironmentSpecularLevels = 6;
inline constexpr int kEnvironmentSpecularBaseWidth = 256;
inline constexpr int kEnvironmentSpecularMinWidth = 8;
inline constexpr int kEnvironmentIrradianceWidth = 32;
inline constexpr int kEnvironmentIrradianceSourceWidth = 64;
inline constexpr int kEnvironmentIrradianceSplit = 16;

struct PrefilteredEnvironment {
  std::vector<Image> specular_levels;  ///< kEnvironmentSpecularLevels maps, finest first
  Image irradiance;                    ///< E(n) [W/m^2]
};

/// The width of specular level m for a map of width W.
int environment_specular_width(int map_width, int level);
/// GGX alpha of specular level m: (m / (kEnvironmentSpecularLevels - 1))^2, i.e. perceptual
/// roughness m / (levels - 1) (Karis 2013's alpha = roughness^2).
double environment_specular_alpha(int level);
/// The GGX samples per texel of level m >= 1 (more for the wider lobes of the coarser levels).
int environment_specular_samples(int level);

/// The map replicated texel for texel (the same piecewise-constant light) until it is at least as
/// wide as the specular chain's base: the chain then starts at kEnvironmentSpecularBaseWidth and
/// halves down to its coarsest level, a GL mip chain whatever the map's size.
Image widened_for_specular_chain(const Image& map);

std::vector<Image> prefilter_environment_specular(const Image& radiance);
Image environment_irradiance(const Image& radiance);
/// Both of the above.
PrefilteredEnvironment prefilter_environment(const Image& radiance);

}  // namespace glintlab
