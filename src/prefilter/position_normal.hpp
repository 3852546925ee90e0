#pragma once
// Position-normal distributions (Yan et al. 2016, "Position-Normal Distributions for Efficient
// Rendering of Specular Microstructure", SIGGRAPH 2016): the NDF of the part of a normal-mapped
// surface that a Gaussian pixel footprint sees, evaluated by brute force over Gaussian elements.
// This is the exact baseline `yan2016` (its GLSL twin is shaders/glints/normal-map/position_normal.glsl) and
// the source of every NDF image deng2022 precomputes. docs/methods.md#yan2016 has the derivation.
#include <cmath>
#include <cstdint>
#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "prefilter/ndf_image.hpp"
#include "prefilter/normal_field.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// A Gaussian pixel footprint in the map's texel space.
struct Footprint {
  glm::dvec2 centre{0.0};
  glm::dmat2 covariance{1.0};

  static Footprint isotropic(glm::dvec2 centre, double sigma) { return {centre, glm::dmat2(sigma * sigma)}; }
};

/// Some of the elements: those whose index (ex, ey) lies in [lo, hi) (the element grid, k per texel
/// and axis, before wrapping): a Wang tile's (prefilter/wang_tile_pyramids.hpp).
struct ElementWindow {
  glm::ivec2 lo{0}, hi{0};
};

/// An element's shape at k elements per texel and axis: an isotropic Gaussian of this standard
/// deviation in texels, 1.5 / (k sqrt 12) (a box of the element's spacing, widened by 1.5 so that
/// neighbours overlap).
inline double position_normal_element_sigma(int elements_per_texel) { return 1.5 / (elements_per_texel * std::sqrt(12.0)); }

/// Elements farther than this Mahalanobis distance from the footprint's centre (under the sum of
/// the element's and the footprint's covariances) are skipped, in the sum and in its normaliser.
inline constexpr double kElementTruncation = 3.0;

class PositionNormalDistribution {
 public:
  /// `intrinsic_roughness`: sigma_r, the standard deviation of the projected normal about the map's;
  /// `elements_per_texel`: k, the elements per texel and axis (1 or 2).
  PositionNormalDistribution(const NormalMap& map, double intrinsic_roughness, int elements_per_texel = 1);

  struct Element {
    glm::vec2 projected;  ///< p_e = n(u_e).xy
    glm::mat2 jacobian;   ///< dp/du at u_e
  };

  [[nodiscard]] int width() const { return field_.width(); }
  [[nodiscard]] int height() const { return field_.height(); }
  [[nodiscard]] double intrinsic_roughness() const { return sigma_r_; }
  [[nodiscard]] int elements_per_texel() const { return k_; }
  /// Every element, (width k) x (height k), row major.
  [[nodiscard]] const std::vector<Element>& elements() const { return elements_; }
  /// Element shape: position_normal_element_sigma(k).
  [[nodiscard]] double element_sigma() const;
  /// The smallest square half-width that holds every element's mean plus 4 of its deviations.
  [[nodiscard]] double suggested_extent() const;

  /// P(s): the footprint's NDF over the projected half vector, a density over the plane.
  [[nodiscard]] double density(const Footprint& footprint, glm::dvec2 s) const;
  /// The mean of P over the box [lo, hi]: each element's Gaussian integrated over the box, exactly
  /// along y given x and by 10-point Gauss-Legendre along x (as the GLSL range query).
  [[nodiscard]] double range_mean(const Footprint& footprint, glm::dvec2 lo, glm::dvec2 hi) const;
  /// The footprint's NDF image on `grid` (pixel averages, see ndf_image.hpp). With a `window`, the
  /// part of it that the window's elements make: their terms over the weight of every element of
  /// the plane the footprint reaches (its mass is the window's share of the footprint).
  [[nodiscard]] NdfImage image(const Footprint& footprint, const NdfGrid& grid,
                               const ElementWindow* window = nullptr) const;
  /// Adds the footprint's NDF image (pixel averages) into `out` (grid.pixel_count() floats) times `scale`.
  void accumulate_image(const Footprint& footprint, const NdfGrid& grid, double scale, float* out,
                        const ElementWindow* window = nullptr) const;

  /// One element in the footprint's sum: its weight and the Gaussian it adds over s.
  struct Term {
    double weight;
    glm::dvec2 mean;
    glm::dmat2 covariance;
  };
  /// Calls `term` for every element within the truncation (with a `window`, only for the window's);
  /// returns the sum of the weights of every element within the truncation, in the window or not.
  template <typename F>
  double for_each_term(const Footprint& footprint, F&& term, const ElementWindow* window = nullptr) const;

 private:
  [[nodiscard]] const Element& element(int ex, int ey) const;

  NormalField field_;
  double sigma_r_;
  int k_;
  std::vector<Element> elements_;  ///< (width k) x (height k), row major
};

/// The footprint's NDF of the surface itself, by Monte Carlo: positions u ~ N(centre, covariance),
/// normals from the bilinear field, s = n(u).xy + sigma_r N(0, I), binned on `grid` (pixel averages).
/// The ground truth that PositionNormalDistribution's elements approximate (tests, docs).
NdfImage surface_ndf_histogram(const NormalMap& map, double intrinsic_roughness, const Footprint& footprint,
                               const NdfGrid& grid, std::uint64_t samples, std::uint32_t seed);

}  // namespace glintlab

// ---- implementation of the template ----
#include <cmath>
#include <glm/matrix.hpp>
#include <vector>

namespace glintlab {

template <typename F>
double PositionNormalDistribution::for_each_term(const Footprint& footprint, F&& term, const ElementWindow* window) const {
  // Element e is the Gaussian N(u; u_e, Sigma_h) carrying the linearised normal
  // p(u) = p_e + J_e (u - u_e); the footprint is N(u; c, Sigma_p). Their product is
  // w_e N(u; m_e, Sigma_u) with w_e = N(c; u_e, Sigma_h + Sigma_p) (Yan et al. 2016, sec. 4), so s =
  // p(u) + sigma_r N(0, I) is Gaussian with mean p_e + J_e (m_e - u_e), covariance
  // J_e Sigma_u J_e^T + sigma_r^2 I, where m_e - u_e = Sigma_h (Sigma_h + Sigma_p)^-1 (c - u_e)
  // and Sigma_u = Sigma_h - Sigma_h (Sigma_h + Sigma_p)^-1 Sigma_h (no inverse of Sigma_p needed).
  const double sh2 = element_sigma() * element_sigma();
  const glm::dmat2 sigma_h(sh2);
  const glm::dmat2 sigma_w = sigma_h + footprint.covariance;
  const glm::dmat2 sigma_w_inv = glm::inverse(sigma_w);
  const glm::dmat2 gain = sigma_h * sigma_w_inv;
  const glm::dmat2 sigma_u = sigma_h - gain * sigma_h;
  const glm::dmat2 intrinsic(sigma_r_ * sigma_r_);
  const glm::dvec2 reach = kElementTruncation * glm::sqrt(glm::dvec2(sigma_w[0][0], sigma_w[1][1]));
  const glm::dvec2 c = footprint.centre;
  const int x0 = static_cast<int>(std::ceil(k_ * (c.x - reach.x) - 0.5));
  const int x1 = static_cast<int>(std::floor(k_ * (c.x + reach.x) - 0.5));
  const int y0 = static_cast<int>(std::ceil(k_ * (c.y - reach.y) - 0.5));
  const int y1 = static_cast<int>(std::floor(k_ * (c.y + reach.y) - 0.5));
  const double limit2 = kElementTruncation * kElementTruncation;
  const auto visit = [&](int ex, int ey, double& total) {
    const glm::dvec2 d = c - glm::dvec2(ex + 0.5, ey + 0.5) / static_cast<double>(k_);
    const double m2 = glm::dot(d, sigma_w_inv * d);
    if (m2 > limit2) return;
    const Element& e = element(ex, ey);
    const glm::dmat2 j(e.jacobian);
    const double w = std::exp(-0.5 * m2);
    total += w;
    term(Term{w, glm::dvec2(e.projected) + j * (gain * d), j * sigma_u * glm::transpose(j) + intrinsic});
  };
  double total = 0.0;
  if (!window) {
    for (int ey = y0; ey <= y1; ++ey)
      for (int ex = x0; ex <= x1; ++ex) visit(ex, ey, total);
    return total;
  }
  double inside = 0.0;
  for (int ey = std::max(y0, window->lo.y); ey <= std::min(y1, window->hi.y - 1); ++ey)
    for (int ex = std::max(x0, window->lo.x); ex <= std::min(x1, window->hi.x - 1); ++ex) visit(ex, ey, inside);
  // The weight of every element of the plane within the truncation. Axis-aligned (the precompute's
  // round footprints): row by row, the row's factor times a prefix sum of the column factors over
  // the columns inside the ellipse, O(rows + columns); otherwise element by element.
  const double inv00 = sigma_w_inv[0][0], inv01 = sigma_w_inv[0][1], inv11 = sigma_w_inv[1][1];
  const auto dx_of = [&](int ex) { return c.x - (ex + 0.5) / k_; };
  const auto dy_of = [&](int ey) { return c.y - (ey + 0.5) / k_; };
  if (inv01 == 0.0 && x1 >= x0) {
    std::vector<double> prefix(static_cast<std::size_t>(x1 - x0 + 2), 0.0);
    for (int ex = x0; ex <= x1; ++ex)
      prefix[static_cast<std::size_t>(ex - x0 + 1)] =
          prefix[static_cast<std::size_t>(ex - x0)] + std::exp(-0.5 * inv00 * dx_of(ex) * dx_of(ex));
    for (int ey = y0; ey <= y1; ++ey) {
      const double dy = dy_of(ey), left = limit2 - inv11 * dy * dy;
      if (left < 0.0) continue;
      // The columns with inv00 dx^2 <= left: |c.x - (ex + 0.5) / k| <= r.
      const double r = std::sqrt(left / inv00);
      const int a = std::max(x0, static_cast<int>(std::ceil(k_ * (c.x - r) - 0.5)));
      const int b = std::min(x1, static_cast<int>(std::floor(k_ * (c.x + r) - 0.5)));
      if (b >= a)
        total += std::exp(-0.5 * inv11 * dy * dy) *
                 (prefix[static_cast<std::size_t>(b - x0 + 1)] - prefix[static_cast<std::size_t>(a - x0)]);
    }
    return total;
  }
  for (int ey = y0; ey <= y1; ++ey)
    for (int ex = x0; ex <= x1; ++ex) {
      const double dx = dx_of(ex), dy = dy_of(ey);
      const double m2 = inv00 * dx * dx + 2.0 * inv01 * dx * dy + inv11 * dy * dy;
      if (m2 <= limit2) total += std::exp(-0.5 * m2);
    }
  return total;
}

}  // namespace glintlab
