#pragma once
// The normals of a sum of cosine waves with integer frequencies over the unit tile (the `bumps` and
// `brushed` generators): height(p) = a sum_w cos(2 pi k_w . p + phase_w), sampled at texel centres.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace glintlab {

struct BumpWave {
  glm::ivec2 k;  ///< cycles per tile along u and v
  float phase;
};

struct BumpSpectrum {
  std::vector<BumpWave> waves;
  double amplitude = 0;  ///< a
};

/// Random waves with distinct integer frequencies of length 1 .. max_frequency and random phases,
/// scaled so the slope variance over the tile is slope_sigma^2 (docs of generate_bumps).
BumpSpectrum choose_bump_waves(float slope_sigma, int waves, int max_frequency, std::uint32_t seed, float anisotropy,
                               float angle_degrees);

/// Brushed metal: frequencies drawn from an anisotropic Gaussian (Heitz's procedural Beckmann
/// surfaces), rounded to distinct integers of at most max_frequency per axis. Its standard deviation
/// is across_alpha across and along_alpha along the brushing direction (`angle_degrees` from +u
/// towards +v), scaled so the rougher axis has max_frequency / 3; the amplitude makes the slope
/// variance of both axes together (across_alpha^2 + along_alpha^2) / 2, which the Gaussian splits
/// as across_alpha^2 / 2 across and along_alpha^2 / 2 along (up to the sampling of the waves).
BumpSpectrum choose_brushed_waves(float across_alpha, float along_alpha, float angle_degrees, int waves,
                                  int max_frequency, std::uint32_t seed);

/// Normals normalize(-dh/du, -dh/dv, 1) at the texel centres of a resolution^2 tile, row 0 at
/// v = 0. Row by row: each row's waves are binned by their u frequency and summed along the row
/// by one inverse DFT, O(resolution * (waves + resolution log resolution)) instead of
/// O(resolution^2 * waves), on every hardware thread. Progress is reported per row as `what`.
std::vector<glm::vec3> bump_normals(const BumpSpectrum& spectrum, int resolution, const std::string& what);

/// The same normals summed wave by wave at each texel in double precision: the definition,
/// O(resolution^2 * waves), kept to test and benchmark bump_normals against.
std::vector<glm::vec3> bump_normals_per_wave(const BumpSpectrum& spectrum, int resolution);

}  // namespace glintlab
