// The specular chain of environment_prefilter.hpp: GGX-filtered importance sampling of a mip
// pyramid of the radiance (Karis 2013; Krivanek & Colbert 2008). The irradiance map is
// environment_irradiance.cpp's.
#include "scene/lights/environment_prefilter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "scene/lights/environment_map.hpp"

namespace glintlab {
namespace {

/// Van der Corput's radical inverse in base 2: the second coordinate of a Hammersley set.
double radical_inverse_2(std::uint32_t i) {
  std::uint32_t bits = i;
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
  bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
  bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
  return bits * (1.0 / 4294967296.0);
}

/// A reflected direction about r = z in r's frame, its weight n.l and the base-2 log of its
/// sample's solid angle Omega_s = 1 / (N pdf(l)).
struct LobeSample {
  glm::dvec3 l;
  double weight;
  double log2_solid_angle;
};

/// The lobe's samples: h from D(h) (n.h) of GGX (Walter et al. 2007, eqs. 35-36, as
/// cos^2 theta_h = (1 - u) / (1 + (alpha^2 - 1) u)) on a Hammersley set; with n = v the density of
/// l = reflect(-v, h) is D(h) (n.h) / (4 v.h) = D(h) / 4. Samples below the horizon are dropped.
std::vector<LobeSample> lobe_samples(double alpha, int count) {
  std::vector<LobeSample> samples;
  const double a2 = alpha * alpha;
  for (int i = 0; i < count; ++i) {
    const double u = (i + 0.5) / count, phi = 2 * std::numbers::pi * radical_inverse_2(static_cast<std::uint32_t>(i));
    const double cos2 = (1 - u) / (1 + (a2 - 1) * u);
    const double cos_h = std::sqrt(cos2), sin_h = std::sqrt(std::max(0.0, 1 - cos2));
    const glm::dvec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
    const glm::dvec3 l = 2 * cos_h * h - glm::dvec3(0, 0, 1);
    if (l.z <= 0) continue;
    const double e = cos2 * (a2 - 1) + 1;
    const double ndf = a2 / (std::numbers::pi * e * e);  // Walter et al. 2007, eq. 33
    samples.push_back({l, l.z, -std::log2(count * ndf / 4)});
  }
  return samples;
}

/// The map and its box-filtered mips (downsample_environment halves each), down to 4 x 2.
class MipPyramid {
 public:
  explicit MipPyramid(const Image& radiance) {
    levels_.push_back(radiance);
    while (levels_.back().height() >= 4 && levels_.back().height() % 2 == 0)
      levels_.push_back(downsample_environment(levels_.back(), levels_.back().height() / 2));
  }
  [[nodiscard]] int levels() const { return static_cast<int>(levels_.size()); }
  [[nodiscard]] const Image& level(int k) const { return levels_[static_cast<std::size_t>(k)]; }

  /// Trilinear: bilinear within mips floor(lod) and floor(lod) + 1, wrapping in u, clamped in v.
  [[nodiscard]] glm::dvec3 fetch(glm::dvec2 uv, double lod) const {
    lod = std::clamp(lod, 0.0, double(levels() - 1));
    const int k = std::min(static_cast<int>(lod), levels() - 1);
    const double t = lod - k;
    const glm::dvec3 fine = bilinear(levels_[static_cast<std::size_t>(k)], uv);
    if (t <= 0 || k + 1 >= levels()) return fine;
    return glm::mix(fine, bilinear(levels_[static_cast<std::size_t>(k + 1)], uv), t);
  }

 private:
  static glm::dvec3 bilinear(const Image& image, glm::dvec2 uv) {
    const int w = image.width(), h = image.height();
    const double x = uv.x * w - 0.5, y = std::clamp(uv.y * h - 0.5, 0.0, h - 1.0);
    const int x0 = static_cast<int>(std::floor(x)), y0 = std::min(static_cast<int>(y), h - 1);
    const double fx = x - x0, fy = y - y0;
    const int xa = ((x0 % w) + w) % w, xb = (xa + 1) % w, y1 = std::min(y0 + 1, h - 1);
    const glm::dvec3 top = glm::mix(glm::dvec3(image.at(xa, y0)), glm::dvec3(image.at(xb, y0)), fx);
    const glm::dvec3 bottom = glm::mix(glm::dvec3(image.at(xa, y1)), glm::dvec3(image.at(xb, y1)), fx);
    return glm::mix(top, bottom, fy);
  }
  std::vector<Image> levels_;
};

/// An orthonormal frame (t, b, n) about unit n (Duff et al. 2017, "Building an Orthonormal Basis,
/// Revisited", listing 3).
void frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1 / (sign + n.z), c = n.x * n.y * a;
  t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

Image filter_level(const MipPyramid& source, int width, double alpha, int sample_count) {
  const std::vector<LobeSample> samples = lobe_samples(alpha, sample_count);
  const Image& base = source.level(0);
  // Omega_p: the solid angle of a finest texel at polar angle theta is (2 pi / W)(pi / H) sin(theta).
  const double log2_texel = std::log2(2 * std::numbers::pi * std::numbers::pi / (double(base.width()) * base.height()));
  Image result(width, width / 2);
  for (int y = 0; y < result.height(); ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 r = environment_direction_precise((x + 0.5) / width, (y + 0.5) / result.height());
      glm::dvec3 t, b;
      frame(r, t, b);
      glm::dvec3 sum(0.0);
      double weights = 0;
      for (const LobeSample& s : samples) {
        const glm::dvec3 l = s.l.x * t + s.l.y * b + s.l.z * r;
        const double sin_theta = std::sqrt(std::max(1e-8, 1 - l.y * l.y));
        // Krivanek & Colbert 2008: the mip whose texels match the sample's solid angle, one finer
        // than log4(Omega_s / Omega_p) (the +1), so that neighbouring samples' footprints overlap.
        const double lod = 0.5 * (s.log2_solid_angle - log2_texel - std::log2(sin_theta)) + 1;
        sum += s.weight * source.fetch(environment_uv(l), lod);
        weights += s.weight;
      }
      result.at(x, y) = glm::vec3(sum / weights);
    }
  return result;
}

}  // namespace

int environment_specular_width(int map_width, int level) {
  // A map narrower than the minimum (4 x 2) keeps its own width: level 0 is never upsampled.
  const int floor_width = std::min(map_width, kEnvironmentSpecularMinWidth);
  return std::max(floor_width, std::min(map_width, kEnvironmentSpecularBaseWidth) >> level);
}

double environment_specular_alpha(int level) {
  const double roughness = double(level) / (kEnvironmentSpecularLevels - 1);
  return roughness * roughness;
}

int environment_specular_samples(int level) {
  // Level 1 has 4x the texels of level 2 and a lobe 4x narrower (alpha 0.04): fewer samples there.
  return level <= 1 ? 64 : level == 2 ? 128 : 256;
}

Image widened_for_specular_chain(const Image& map) {
  const int factor = (kEnvironmentSpecularBaseWidth + map.width() - 1) / map.width();
  if (factor <= 1) return map;
  Image wide(map.width() * factor, map.height() * factor);
  for (int y = 0; y < wide.height(); ++y)
    for (int x = 0; x < wide.width(); ++x) wide.at(x, y) = map.at(x / factor, y / factor);
  return wide;
}

std::vector<Image> prefilter_environment_specular(const Image& radiance) {
  const MipPyramid source(radiance);
  std::vector<Image> levels;
  levels.push_back(downsample_environment(radiance, environment_specular_width(radiance.width(), 0) / 2));
  for (int m = 1; m < kEnvironmentSpecularLevels; ++m)
    levels.push_back(filter_level(source, environment_specular_width(radiance.width(), m), environment_specular_alpha(m),
                                  environment_specular_samples(m)));
  return levels;
}

PrefilteredEnvironment prefilter_environment(const Image& radiance) {
  return {prefilter_environment_specular(radiance), environment_irradiance(radiance)};
}

}  // namespace glintlab
