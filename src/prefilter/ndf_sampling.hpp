#pragma once
// Importance sampling of a pixel footprint's NDF over projected half vectors s = h.xy: Deng et
// al. 2022's sampler of the compressed pyramid (sec. 5.2) and Yan et al. 2016's of the element
// mixture. Each sampler's density is the NDF its method evaluates, over that NDF's mass, so that
// MIS weights and estimators built from the evaluation stay consistent (docs/methods.md#deng2022).
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "prefilter/position_normal.hpp"
#include "prefilter/prefiltered_ndf.hpp"

namespace glintlab {

struct NdfSample {
  glm::dvec2 s;  ///< the projected half vector
  double pdf;    ///< its density over the plane of s
};

/// Deng et al. 2022, sec. 5.2: one of the trilinear blend's stored footprints by its weight times
/// its mass, one of its kept blocks by its range mass, the block's pixel by range queries down a
/// quadtree of its pixels, then the pixel's centre plus a tent offset along each axis (a tent is
/// the pixel's box convolved with itself, so the samples' density is exactly the bilinear
/// interpolation `density` evaluates). u: three uniforms in [0, 1), the first reused down the
/// discrete choices. Nothing when the footprint's NDF has no mass in the square.
std::optional<NdfSample> sample_prefiltered_ndf(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma,
                                                glm::dvec3 u);
/// The footprint's mass in the square: the integral of `density` (the sampler's normaliser).
double prefiltered_ndf_mass(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma);
/// The sampler's density at s: density(centre, sigma, s) / mass.
double prefiltered_ndf_pdf(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma, glm::dvec2 s);

/// Yan et al. 2016's mixture: an element by its weight, then a point of its Gaussian (Box-Muller
/// through the covariance's Cholesky factor). The mixture is normalised, so the pdf is `density`.
std::optional<NdfSample> sample_position_normal(const PositionNormalDistribution& pnd, const Footprint& footprint,
                                                glm::dvec3 u);

}  // namespace glintlab
