#pragma once
// Footprints after rough bounces: a ray cone (Amanatides 1984; as ray tracers keep texture
// footprints, Akenine-Moller et al. 2019) carried along each path, widened by the angular spread of
// every rough lobe it bounces off. Deng et al. 2022 sec. 5.3 render glinty interreflection with "the
// indirect footprint computation by Wang et al. (2018): accurate footprints for the direct
// footprint, amplified considering the glossiness during the following bounces"; this is that
// rule in its first-order form: a lobe of per-axis angular deviation sigma widens the footprint by
// sigma t after a distance t, and the widenings of successive lobes add.
#include <glm/glm.hpp>
#include <utility>

namespace glintlab {

struct RayCone {
  float width = 0.0f;   ///< the cross-section's deviation at the ray's origin, per axis [m]
  float spread = 0.0f;  ///< its growth per unit length: the deviations of the lobes bounced off [rad]

  /// The cone at distance t along the ray.
  [[nodiscard]] RayCone travelled(float t) const { return {width + spread * t, spread}; }
  /// The cone leaving a lobe of per-axis angular deviation `lobe_spread` (0: a mirror).
  [[nodiscard]] RayCone bounced(float lobe_spread) const { return {width, spread + lobe_spread}; }
};

/// The per-axis angular deviation of a direction sampled from a lobe: a microfacet lobe of roughness
/// alpha reflects about normals of slope deviation alpha / sqrt(2) (Beckmann; GGX's slopes have no
/// finite variance and are given Beckmann's), and reflection doubles the angle: sqrt(2) alpha; a
/// cosine (diffuse) lobe's direction has per-axis deviation 1/2. At most 1/2.
float lobe_spread(float alpha, bool diffuse);

/// The footprint steps (dPdx, dPdy) on a surface of unit normal `normal`, hit by a ray of unit
/// `direction`, widened by a cone cross-section of deviation `width`: two steps whose covariance
/// dPdx dPdx^T + dPdy dPdy^T is the footprint's plus the cross-section's, projected onto the
/// surface along the ray. A step of length L is a footprint of deviation `sigma` L (the methods'
/// footprint_sigma, kPixelFilterSigma by default), so the cross-section enters as steps of width /
/// sigma. The steps come back along the covariance's principal axes; unchanged when width is 0.
std::pair<glm::vec3, glm::vec3> widen_footprint(glm::vec3 dPdx, glm::vec3 dPdy, glm::vec3 direction, glm::vec3 normal,
                                                float width, float sigma);

}  // namespace glintlab
