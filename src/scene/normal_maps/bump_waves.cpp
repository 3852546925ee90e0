#include "scene/normal_maps/bump_waves.hpp"

#include <cmath>
#include <complex>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <random>
#include <unordered_set>

#include "core/exponential_sum.hpp"
#include "scene/normal_maps/parallel_rows.hpp"

namespace glintlab {

namespace {

/// Texel centre coordinate. (Before the row sums it was rounded to float, the same value at the
/// power-of-two resolutions and within 2^-24 of the tile at the others.)
double texel_centre(int i, int resolution) { return (i + 0.5) / resolution; }

glm::vec3 normal_from_slope(double du, double dv) {
  return glm::normalize(glm::vec3(-static_cast<float>(du), -static_cast<float>(dv), 1.0f));
}

}  // namespace

namespace {

/// `waves` waves with distinct integer frequencies (k and -k are the same wave), so the waves stay
/// orthogonal over the tile and the slope variance is exactly the sum of theirs. `draw(rng, uni)`
/// proposes a rounded frequency; each accepted one gets a uniform phase. Stops early when 1000
/// proposals in a row are zero or taken (fewer distinct frequencies than waves asked for).
template <class Draw>
std::vector<BumpWave> distinct_waves(int waves, std::uint32_t seed, Draw draw) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  std::vector<BumpWave> ws;
  ws.reserve(static_cast<std::size_t>(waves));
  std::unordered_set<std::int64_t> taken_set;
  auto key = [](glm::vec2 q) {  // one key for k and -k
    if (q.x < 0.0f || (q.x == 0.0f && q.y < 0.0f)) q = -q;
    return static_cast<std::int64_t>(q.x) * (1LL << 32) + static_cast<std::int64_t>(q.y);
  };
  auto taken = [&](glm::vec2 q) { return taken_set.contains(key(q)); };
  for (int i = 0; i < waves; ++i) {
    glm::vec2 k(0.0f);
    for (int attempt = 0; attempt < 1000 && (k == glm::vec2(0.0f) || taken(k)); ++attempt) k = draw(rng, uni);
    if (k == glm::vec2(0.0f) || taken(k)) break;
    ws.push_back({glm::ivec2(k), glm::two_pi<float>() * uni(rng)});
    taken_set.insert(key(k));
  }
  return ws;
}

}  // namespace

BumpSpectrum choose_bump_waves(float slope_sigma, int waves, int max_frequency, std::uint32_t seed, float anisotropy,
                               float angle_degrees) {
  const float axis = glm::radians(angle_degrees);
  std::vector<BumpWave> ws =
      distinct_waves(waves, seed, [&](std::mt19937& rng, std::uniform_real_distribution<float>& uni) {
        const float r = 1.0f + (static_cast<float>(max_frequency) - 1.0f) * std::sqrt(uni(rng));
        // Isotropic: any direction. Anisotropic: a deviation from the axis in [-pi/2, pi/2) (k
        // and -k are one wave) narrowed by the anisotropy.
        const float u = uni(rng);
        const float theta = anisotropy == 1.0f ? glm::two_pi<float>() * u
                                               : axis + glm::pi<float>() * (u - 0.5f) / anisotropy;
        return glm::round(glm::vec2(r * std::cos(theta), r * std::sin(theta)));
      });
  double k2_sum = 0.0;
  for (const BumpWave& w : ws) k2_sum += glm::dot(glm::vec2(w.k), glm::vec2(w.k));
  // height = a * sum cos(2 pi k.x + phase); over a tile the slope variance of both axes together
  // is a^2 (2 pi)^2 sum(|k|^2) / 2. Make it slope_sigma^2 (Beckmann: alpha^2 = <slope^2>).
  return {ws, slope_sigma * std::sqrt(2.0) / (glm::two_pi<double>() * std::sqrt(k2_sum))};
}

BumpSpectrum choose_brushed_waves(float across_alpha, float along_alpha, float angle_degrees, int waves,
                                  int max_frequency, std::uint32_t seed) {
  const float axis = glm::radians(angle_degrees);
  const glm::vec2 along(std::cos(axis), std::sin(axis)), across(-along.y, along.x);
  // Heitz's procedural Beckmann surface: frequencies from a Gaussian whose standard deviations
  // per axis are proportional to the roughness wanted along that axis (equal-amplitude waves:
  // slope variance per axis ~ E[(k.e)^2]). The rougher axis gets max_frequency / 3, so 3 sigma
  // fits; proposals beyond max_frequency (per uv axis) are redrawn.
  const float widest = std::max(across_alpha, along_alpha);
  const float sigma = static_cast<float>(max_frequency) / 3.0f / (widest > 0.0f ? widest : 1.0f);
  std::vector<BumpWave> ws =
      distinct_waves(waves, seed, [&](std::mt19937& rng, std::uniform_real_distribution<float>& uni) {
        // Box-Muller: two independent standard normals.
        const float r = std::sqrt(-2.0f * std::log(1.0f - uni(rng)));
        const float theta = glm::two_pi<float>() * uni(rng);
        const glm::vec2 k = glm::round(sigma * (across_alpha * r * std::cos(theta) * across +
                                                along_alpha * r * std::sin(theta) * along));
        const float limit = static_cast<float>(max_frequency);
        return std::abs(k.x) <= limit && std::abs(k.y) <= limit ? k : glm::vec2(0.0f);
      });
  // Both axes together: a^2 (2 pi)^2 sum(|k|^2) / 2 = (across^2 + along^2) / 2, the Beckmann
  // alpha^2 / 2 of each axis; the split between the axes follows the Gaussian's shape.
  double k2_sum = 0.0;
  for (const BumpWave& w : ws) k2_sum += glm::dot(glm::dvec2(w.k), glm::dvec2(w.k));
  const double total = 0.5 * (static_cast<double>(across_alpha) * across_alpha +
                              static_cast<double>(along_alpha) * along_alpha);
  return {ws, k2_sum > 0.0 ? std::sqrt(2.0 * total) / (glm::two_pi<double>() * std::sqrt(k2_sum)) : 0.0};
}

std::vector<glm::vec3> bump_normals(const BumpSpectrum& spectrum, int resolution, const std::string& what) {
  using Complex = std::complex<double>;
  const int n = resolution;
  const double two_pi = glm::two_pi<double>();
  // Both slopes at once as s = du + i dv. With theta = 2 pi k.p + phase, a wave adds
  // -a 2 pi (k_u + i k_v) sin(theta) = d (e^{i theta} - e^{-i theta}), d = a 2 pi (i k_u - k_v) / 2.
  // Along a row theta = 2 pi k_u x / n + beta_y, so the wave adds d e^{i beta} to the row's
  // u-frequency bin k_u and -d e^{-i beta} to bin -k_u (mod n: |k_u| <= n / 2, and the bins'
  // exponentials at integer x repeat with period n); one inverse DFT then sums the row.
  struct RowWave {
    Complex d;
    int bin_plus, bin_minus;
    double row_phase_offset;  ///< beta at v = 0: the half-texel shift pi k_u / n plus the phase
    double v_frequency;       ///< 2 pi k_v
  };
  std::vector<RowWave> row_waves;
  row_waves.reserve(spectrum.waves.size());
  for (const BumpWave& w : spectrum.waves)
    row_waves.push_back({spectrum.amplitude * two_pi * 0.5 * Complex(-w.k.y, w.k.x), ((w.k.x % n) + n) % n,
                         ((-w.k.x % n) + n) % n, glm::pi<double>() * w.k.x / n + w.phase, two_pi * w.k.y});
  const ExponentialSum row_sum(n);
  const int workers = row_workers(n);
  std::vector<std::vector<Complex>> bins(workers, std::vector<Complex>(n)), scratch(workers);
  std::vector<glm::vec3> normals(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for_each_row(
      n,
      workers,
      [&](int y, int worker) {
        std::vector<Complex>& z = bins[worker];
        std::fill(z.begin(), z.end(), Complex(0.0));
        const double v = texel_centre(y, n);
        for (const RowWave& w : row_waves) {
          const Complex e = std::polar(1.0, w.row_phase_offset + w.v_frequency * v);
          z[w.bin_plus] += w.d * e;
          z[w.bin_minus] -= w.d * std::conj(e);
        }
        row_sum.evaluate(z, scratch[worker]);
        glm::vec3* out = normals.data() + static_cast<std::size_t>(y) * n;
        for (int x = 0; x < n; ++x) out[x] = normal_from_slope(z[x].real(), z[x].imag());
      },
      what);
  return normals;
}

std::vector<glm::vec3> bump_normals_per_wave(const BumpSpectrum& spectrum, int resolution) {
  std::vector<glm::vec3> normals;
  normals.reserve(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution));
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const glm::dvec2 p(texel_centre(x, resolution), texel_centre(y, resolution));
      glm::dvec2 slope(0.0);
      for (const BumpWave& w : spectrum.waves) {
        const double s = -std::sin(glm::two_pi<double>() * glm::dot(glm::dvec2(w.k), p) + w.phase);
        slope += spectrum.amplitude * glm::two_pi<double>() * s * glm::dvec2(w.k);
      }
      normals.push_back(normal_from_slope(slope.x, slope.y));
    }
  return normals;
}

}  // namespace glintlab
