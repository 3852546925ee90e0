#pragma once
// An environment light as a sum of spherical Gaussians (SGs), the basis Deng et al. 2022 prefilter
// glints under environment light with (sec. 5.4, after Tsai and Shih 2006): each lobe is one
// angular range query of the pixel's NDF instead of many samples of the map. The fit:
//   L(d) ~ sum_k a_k exp(lambda (xi_k . d - 1)),
// First the map's compact sources far brighter than the rest (a sun: up to K / 8 of them, each
// over 64 times the map's mean luminance), each one lobe of its own axis, sharpness (from its
// spread) and power, taken out of the map. Then, on what they leave, the other lobes: axes xi_k on
// a spherical Fibonacci lattice, one sharpness lambda for all (chosen from a geometric grid about
// the lattice's spacing: the least error wins), and RGB amplitudes a_k >= 0 by nonnegative least
// squares weighted by each texel's solid angle (coordinate descent on the normal equations),
// scaled per channel so that their power is the rest's. Without the peaks, the L2 fit of a map
// with a sun puts power that belongs to the rest of the sky into the lobes about the sun
// (overshooting to meet its peak), and the scale then takes it from everywhere else. The fit's
// own error is reported: the relative L2 over the map's texels.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/lights/environment_map.hpp"

namespace glintlab {

/// The rows of the map deng2022's and yan2016's lobes are fitted on (or all of a smaller map's).
inline constexpr int kSphericalGaussianFitRows = 64;

struct SphericalGaussian {
  glm::dvec3 axis{0.0, 0.0, 1.0};  ///< unit, in the map's space (environment_map.hpp's convention)
  double sharpness = 1.0;          ///< lambda
  glm::dvec3 amplitude{0.0};       ///< a, RGB radiance at the axis

  /// a exp(lambda (axis . d - 1)) for a unit direction d.
  [[nodiscard]] glm::dvec3 value(const glm::dvec3& d) const;
  /// Its solid angle, the integral over the sphere of exp(lambda (axis . d - 1)): 2 pi (1 - exp(-2 lambda)) / lambda.
  [[nodiscard]] double solid_angle() const;
  /// The integral over the sphere: a times the solid angle.
  [[nodiscard]] glm::dvec3 integral() const { return amplitude * solid_angle(); }
  /// The sine of the half-angle of the cone of the same solid angle, 2 pi (1 - cos) = Omega: the
  /// cone deng2022 and yan2016 shade the lobe as (shaders/glints/normal-map/environment_lobes.glsl).
  [[nodiscard]] double cone_half_angle_sine() const;
  /// A uniform cone about the axis: the sine of its half-angle and its share of the lobe's power.
  struct Cone {
    double sine = 0.0;
    double share = 0.0;
  };
  /// The lobe as three nested uniform cones (environment_lobe_cones = three): their edges hold a
  /// third, two thirds and 95% of its power (its power within angle theta is 1 - exp(lambda (cos
  /// theta - 1)) of the whole); the rings' mean radiances, differenced from the outside in, are the
  /// cones' heights (a layer cake of the radial profile), and the power past 95% is shared by all
  /// alike (the shares sum to 1).
  [[nodiscard]] std::array<Cone, 3> nested_cones() const;
  /// Deng et al.'s eq. 8 (Wang et al. 2009's compact-epsilon support): the angle from the axis
  /// within which the lobe's luminance exceeds epsilon, acos(1 + ln(epsilon / a) / lambda); 0 where
  /// a <= epsilon, pi where the whole sphere exceeds it.
  [[nodiscard]] double support_angle(double epsilon) const;
};

struct SphericalGaussianFit {
  std::vector<SphericalGaussian> lobes;  ///< the peaks first, then the lattice's
  int peaks = 0;                         ///< lobes fitted to the map's compact bright sources
  double relative_error = 0.0;  ///< ||fit - map|| / ||map||, solid-angle weighted L2 over RGB, on the map's texels (at most 256 rows)
  int grid_height = 0;          ///< the rows of the map the fit was made on

  /// The lattice's lobes alone (a map of them has no peak: tests isolate the lobes' shading with it).
  [[nodiscard]] SphericalGaussianFit without_peaks() const;
  /// The fit's radiance in direction d (unit, map space).
  [[nodiscard]] glm::dvec3 radiance(const glm::dvec3& d) const;
  /// Each lobe's probability of being chosen, its luminance integral over the total: how a renderer
  /// importance-samples the SG environment (sec. 5.4: "we first importance sample ... to find one SG").
  [[nodiscard]] std::vector<double> lobe_probabilities() const;
  /// The fit as an environment map of `height` rows, each texel its value at its centre: a light
  /// whose radiance is the lobes' own (the truth that isolates the lobes' shading from the fit).
  [[nodiscard]] EnvironmentMap to_map(int height) const;
};

/// `count` unit directions on the spherical Fibonacci lattice (even over the sphere).
std::vector<glm::dvec3> fibonacci_directions(int count);

/// The fit of `map` with `lobes` SGs (1 .. 1024) on the map resampled to `grid_height` rows (at
/// most its own; downsample_environment keeps its power). Throws InputError for a count or height
/// outside those bounds, naming the value and what is allowed.
SphericalGaussianFit fit_spherical_gaussians(const EnvironmentMap& map, int lobes, int grid_height = 64);

}  // namespace glintlab
