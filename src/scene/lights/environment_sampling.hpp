#pragma once
// Importance sampling an environment map (environment_map.hpp's convention) by its luminance
// times sin(theta): a piecewise-constant 2D distribution over the map's texels, as a marginal CDF
// over rows and one conditional CDF per row (Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 3rd ed., sec. 13.6.7 and 14.2.4).
//
// f(x, y) = luminance(L(x, y)) sin(theta_y), theta_y = pi (y + 0.5) / H (Rec. 709 luminance);
// the integral over uv is I = sum f / (W H). A direction d in texel (x, y) then has the
// uv density f(x, y) / I and the solid-angle density
//     pdf(d) = f(x, y) / I / (2 pi^2 sin(theta(d))),
// since d omega = sin(theta) dtheta dphi = 2 pi^2 sin(theta) du dv. I = 0 means a black map,
// which the GPU never light-samples.
//
// Layout of `cdf`, uploaded as one R32F texture of width W + 1 and height H + 1 (texel (i, j) at
// cdf[j (W + 1) + i]):
// * row y < H: row y's conditional CDF, W + 1 entries from 0 to 1 (cdf[i] = the probability of
//   columns < i); a row whose sum is 0 gets the uniform CDF i / W;
// * row H: the marginal CDF over rows in its first H + 1 entries, 0 first and 1 last (the
//   uniform one if I = 0), the remaining W - H entries 0.
// CDFs are summed in double and stored in float, so every row is non-decreasing with exact 0 and
// 1 ends.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image.hpp"

namespace glintlab {

struct EnvironmentSampling {
  int width = 0;           ///< W, the map's
  int height = 0;          ///< H
  std::vector<float> cdf;  ///< (W + 1) x (H + 1), the layout above
  double integral = 0;     ///< I = sum f / (W H)

  [[nodiscard]] int stride() const { return width + 1; }
  [[nodiscard]] float conditional(int y, int i) const { return cdf[static_cast<std::size_t>(y) * stride() + i]; }
  [[nodiscard]] float marginal(int y) const { return cdf[static_cast<std::size_t>(height) * stride() + y]; }
};

EnvironmentSampling build_environment_sampling(const Image& radiance);

/// The CPU reference of the GPU's sampler (for tests and documentation): uv of the sample of the
/// uniform pair `u` in [0, 1)^2, found by binary search in the marginal CDF, then in the row's
/// conditional, and placed linearly within the texel. `pdf_uv`, if not null, receives its uv
/// density f / I (0 for a black map, which is then sampled uniformly).
glm::dvec2 sample_environment_uv(const EnvironmentSampling& sampling, glm::dvec2 u, double* pdf_uv);

/// The uv density of the texel holding uv, f / I, read from the CDFs as the GPU reads them.
double environment_pdf_uv(const EnvironmentSampling& sampling, glm::dvec2 uv);
/// The solid-angle density of map-space direction d: environment_pdf_uv / (2 pi^2 sin(theta)),
/// 0 at the poles and for a black map.
double environment_pdf(const EnvironmentSampling& sampling, glm::dvec3 d);

}  // namespace glintlab
