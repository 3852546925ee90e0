// The irradiance map of environment_prefilter.hpp: E(n) = integral L(l) max(0, n.l) d omega,
// summed exactly over the texels of a downsampled map.
//
// Over the part of a texel with theta in [t0, t1] and phi in [p0, p1], the integral of the unit
// direction d(theta, phi) = (sin(theta) sin(phi), cos(theta), -sin(theta) cos(phi)) against
// d omega = sin(theta) dtheta dphi is closed-form:
//     V = (S (cos p0 - cos p1), C (p1 - p0), -S (sin p1 - sin p0)),
//     S = int sin^2 = (t1 - t0) / 2 - (sin 2 t1 - sin 2 t0) / 4,  C = int sin cos = (sin^2 t1 - sin^2 t0) / 2,
// so a part wholly above the horizon of n contributes L n.V. A texel the horizon may cross (its
// bounding cone says so) is summed over kEnvironmentIrradianceSplit^2 such parts, each
// max(0, n.V_part): only the parts the horizon crosses keep an error, of second order in their size.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "scene/lights/environment_map.hpp"
#include "scene/lights/environment_prefilter.hpp"

namespace glintlab {
namespace {

constexpr int kSplit = kEnvironmentIrradianceSplit;

/// The theta factors (S, C) of the parts of each row, and the phi factors of the parts of each
/// column, part k of texel i at index i * kSplit + k.
struct PartFactors {
  std::vector<double> s, c;                // per row part
  std::vector<double> sin_int, dphi, cos_int;  // per column part: int sin(phi), p1 - p0, int cos(phi)
};

PartFactors part_factors(int width, int height) {
  PartFactors f;
  const int rows = height * kSplit, columns = width * kSplit;
  for (int j = 0; j < rows; ++j) {
    const double t0 = std::numbers::pi * j / rows, t1 = std::numbers::pi * (j + 1) / rows;
    f.s.push_back(0.5 * (t1 - t0) - 0.25 * (std::sin(2 * t1) - std::sin(2 * t0)));
    f.c.push_back(0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)));
  }
  for (int k = 0; k < columns; ++k) {
    const double p0 = 2 * std::numbers::pi * (double(k) / columns - 0.5), p1 = 2 * std::numbers::pi * (double(k + 1) / columns - 0.5);
    f.sin_int.push_back(std::cos(p0) - std::cos(p1));
    f.dphi.push_back(p1 - p0);
    f.cos_int.push_back(std::sin(p1) - std::sin(p0));
  }
  return f;
}

/// One source texel: its integral of l d omega, and its bounding cone (axis, sin of the margin
/// within which the horizon of n may cross it).
struct TexelCone {
  glm::dvec3 moment{0.0};
  glm::dvec3 axis{0.0};
  double sin_radius = 0;
};

TexelCone texel_cone(const PartFactors& f, int x, int y, int width, int height) {
  TexelCone cone;
  for (int j = 0; j < kSplit; ++j)
    for (int k = 0; k < kSplit; ++k) {
      const std::size_t row = static_cast<std::size_t>(y) * kSplit + j, column = static_cast<std::size_t>(x) * kSplit + k;
      cone.moment += glm::dvec3(f.s[row] * f.sin_int[column], f.c[row] * f.dphi[column], -f.s[row] * f.cos_int[column]);
    }
  cone.axis = glm::normalize(cone.moment);
  // The farthest boundary point from the axis (9 points an edge), with a margin for the arcs between.
  double cos_radius = 1;
  for (int e = 0; e <= 8; ++e)
    for (const glm::dvec2& t : {glm::dvec2(e / 8.0, 0), glm::dvec2(e / 8.0, 1), glm::dvec2(0, e / 8.0), glm::dvec2(1, e / 8.0)})
      cos_radius = std::min(cos_radius, glm::dot(cone.axis, environment_direction_precise((x + t.x) / width, (y + t.y) / height)));
  const double radius = std::min(std::numbers::pi / 2, 1.1 * std::acos(std::clamp(cos_radius, -1.0, 1.0)) + 1e-3);
  cone.sin_radius = std::sin(radius);
  return cone;
}

}  // namespace

Image environment_irradiance(const Image& radiance) {
  const Image source =
      downsample_environment(radiance, std::min(radiance.width(), kEnvironmentIrradianceSourceWidth) / 2);
  const int w = source.width(), h = source.height();
  const PartFactors f = part_factors(w, h);
  std::vector<TexelCone> cones;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) cones.push_back(texel_cone(f, x, y, w, h));

  Image result(kEnvironmentIrradianceWidth, kEnvironmentIrradianceWidth / 2);
  std::vector<double> a(kSplit), b(kSplit);
  for (int oy = 0; oy < result.height(); ++oy)
    for (int ox = 0; ox < result.width(); ++ox) {
      const glm::dvec3 n = environment_direction_precise((ox + 0.5) / result.width(), (oy + 0.5) / result.height());
      glm::dvec3 sum(0.0);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const TexelCone& cone = cones[static_cast<std::size_t>(y) * w + x];
          const double cos_axis = glm::dot(n, cone.axis);
          double weight;  // integral of max(0, n.l) over the texel
          if (cos_axis >= cone.sin_radius) {
            weight = glm::dot(n, cone.moment);  // wholly above the horizon: exact
          } else if (cos_axis <= -cone.sin_radius) {
            continue;  // wholly below
          } else {
            // n.V_part = S (n.x int sin - n.z int cos) + C n.y dphi, factored per column part.
            for (int k = 0; k < kSplit; ++k) {
              const std::size_t column = static_cast<std::size_t>(x) * kSplit + k;
              a[static_cast<std::size_t>(k)] = n.x * f.sin_int[column] - n.z * f.cos_int[column];
              b[static_cast<std::size_t>(k)] = n.y * f.dphi[column];
            }
            weight = 0;
            for (int j = 0; j < kSplit; ++j) {
              const std::size_t row = static_cast<std::size_t>(y) * kSplit + j;
              for (int k = 0; k < kSplit; ++k)
                weight += std::max(0.0, f.s[row] * a[static_cast<std::size_t>(k)] + f.c[row] * b[static_cast<std::size_t>(k)]);
            }
          }
          sum += weight * glm::dvec3(source.at(x, y));
        }
      result.at(ox, oy) = glm::vec3(sum);
    }
  return result;
}

}  // namespace glintlab
