#include "prefilter/position_normal.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

#include "core/error.hpp"

namespace glintlab {

namespace {

double gaussian2(glm::dvec2 x, const glm::dmat2& cov) {
  const double det = glm::determinant(cov);
  if (!(det > 0)) return 0.0;
  return std::exp(-0.5 * glm::dot(x, glm::inverse(cov) * x)) / (glm::two_pi<double>() * std::sqrt(det));
}

/// Standard normal CDF.
double phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double box_integral(const glm::dvec2& mean, const glm::dmat2& cov, glm::dvec2 lo, glm::dvec2 hi) {
  // The integral of N2(mean, cov) over [lo, hi]: y exactly given x (the conditional is a 1D Gaussian),
  // x by 10-point Gauss-Legendre over [lo.x, hi.x] clipped to mean.x +- 5 sigma_x.
  static constexpr double kNodes[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                       0.8650633666889845, 0.9739065285171717};
  static constexpr double kWeights[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                         0.1494513491505806, 0.0666713443086881};
  const double sx = std::sqrt(cov[0][0]);
  const double a = std::max(lo.x, mean.x - 5 * sx), b = std::min(hi.x, mean.x + 5 * sx);
  if (!(a < b)) return 0.0;
  const double slope = cov[0][1] / cov[0][0];  // E[y | x] = mean.y + slope (x - mean.x)
  const double sc = std::sqrt(std::max(cov[1][1] - slope * cov[0][1], 1e-6 * cov[1][1]));
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double x = mid + (i < 5 ? -kNodes[i] : kNodes[i - 5]) * half;
    const double my = mean.y + slope * (x - mean.x);
    const double zx = (x - mean.x) / sx;
    sum += kWeights[i % 5] * std::exp(-0.5 * zx * zx) * (phi((hi.y - my) / sc) - phi((lo.y - my) / sc));
  }
  return sum * half / (std::sqrt(glm::two_pi<double>()) * sx);
}

}  // namespace

double NdfImage::mass() const {
  double sum = 0.0;
  for (float v : values) sum += v;
  return sum * grid.pixel_area();
}

double relative_l2(const NdfImage& a, const NdfImage& b) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = static_cast<double>(a.values[i]) - b.values[i];
    num += d * d;
    den += static_cast<double>(b.values[i]) * b.values[i];
  }
  return den > 0 ? std::sqrt(num / den) : std::sqrt(num);
}

PositionNormalDistribution::PositionNormalDistribution(const NormalMap& map, double intrinsic_roughness,
                                                       int elements_per_texel)
    : field_(map), sigma_r_(intrinsic_roughness), k_(elements_per_texel) {
  if (k_ < 1 || k_ > 4) throw InputError("elements_per_texel is " + std::to_string(k_) + "; allowed: 1 .. 4");
  if (!(sigma_r_ > 0)) throw InputError("intrinsic_roughness must be > 0");
  const int w = map.width * k_, h = map.height * k_;
  elements_.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  const double delta = 0.5 / k_;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 u = glm::dvec2(x + 0.5, y + 0.5) / static_cast<double>(k_);
      elements_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] = {
          glm::vec2(field_.projected(u)), glm::mat2(field_.projected_jacobian(u, delta))};
    }
}

double PositionNormalDistribution::element_sigma() const { return position_normal_element_sigma(k_); }

const PositionNormalDistribution::Element& PositionNormalDistribution::element(int ex, int ey) const {
  const int w = width() * k_, h = height() * k_;
  return elements_[static_cast<std::size_t>(wrap_texel(ey, h)) * static_cast<std::size_t>(w) +
                   static_cast<std::size_t>(wrap_texel(ex, w))];
}

double PositionNormalDistribution::suggested_extent() const {
  double extent = 0.0;
  const double spread = element_sigma();
  for (const Element& e : elements_) {
    const glm::dvec2 p(e.projected);
    const glm::dmat2 j(e.jacobian);
    // The element's mean moves by at most |J| times the element's reach; its deviation adds sigma_r.
    const glm::dvec2 moves(std::abs(j[0][0]) + std::abs(j[1][0]), std::abs(j[0][1]) + std::abs(j[1][1]));
    const glm::dvec2 far = glm::abs(p) + moves * (kElementTruncation * spread) + 4.0 * sigma_r_;
    extent = std::max({extent, far.x, far.y});
  }
  return std::min(extent, 1.0);
}

double PositionNormalDistribution::density(const Footprint& footprint, glm::dvec2 s) const {
  double sum = 0.0;
  const double total =
      for_each_term(footprint, [&](const Term& t) { sum += t.weight * gaussian2(s - t.mean, t.covariance); });
  return total > 0 ? sum / total : 0.0;
}

double PositionNormalDistribution::range_mean(const Footprint& footprint, glm::dvec2 lo, glm::dvec2 hi) const {
  const double area = (hi.x - lo.x) * (hi.y - lo.y);
  if (!(area > 0)) return density(footprint, 0.5 * (lo + hi));
  double sum = 0.0;
  const double total =
      for_each_term(footprint, [&](const Term& t) { sum += t.weight * box_integral(t.mean, t.covariance, lo, hi); });
  return total > 0 ? sum / (total * area) : 0.0;
}

void PositionNormalDistribution::accumulate_image(const Footprint& footprint, const NdfGrid& grid, double scale,
                                                  float* out, const ElementWindow* window) const {
  const int n = grid.resolution;
  const double h = grid.pixel_size();
  const glm::dmat2 box(h * h / 12.0);  // a pixel's box as a Gaussian of the same variance
  std::vector<std::pair<int, double>> stored;
  std::vector<double> pixels(grid.pixel_count(), 0.0);
  const double total = for_each_term(footprint, [&](const Term& t) {
    // The element's Gaussian averaged over each pixel: its values at pixel centres after widening by
    // the pixel's box, renormalised so that the element puts exactly its weight into the image
    // (minus what falls outside the square).
    const glm::dmat2 cov = t.covariance + box;
    const glm::dmat2 inv = glm::inverse(cov);
    const glm::dvec2 centre = grid.to_pixels(t.mean) - 0.5;
    const glm::dvec2 reach = 3.5 * glm::sqrt(glm::dvec2(cov[0][0], cov[1][1])) / h;
    const int i0 = static_cast<int>(std::ceil(centre.x - reach.x)), i1 = static_cast<int>(std::floor(centre.x + reach.x));
    const int j0 = static_cast<int>(std::ceil(centre.y - reach.y)), j1 = static_cast<int>(std::floor(centre.y + reach.y));
    // The box widens every Gaussian to at least h / sqrt(12), so the window spans >= 2 pixels per axis.
    if (i1 < 0 || j1 < 0 || i0 >= n || j0 >= n) return;  // all of it outside the square
    double sum = 0.0;
    stored.clear();
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const glm::dvec2 d = (glm::dvec2(i, j) - centre) * h;
        const double g = std::exp(-0.5 * glm::dot(d, inv * d));
        sum += g;
        if (i >= 0 && j >= 0 && i < n && j < n) stored.emplace_back(j * n + i, g);
      }
    if (!(sum > 0)) {
      const int i = static_cast<int>(std::lround(centre.x)), j = static_cast<int>(std::lround(centre.y));
      if (i >= 0 && j >= 0 && i < n && j < n) pixels[static_cast<std::size_t>(j) * n + i] += t.weight;
      return;
    }
    for (const auto& [index, g] : stored) pixels[static_cast<std::size_t>(index)] += t.weight * g / sum;
  }, window);
  if (!(total > 0)) return;
  const double to_average = scale / (total * grid.pixel_area());
  for (std::size_t i = 0; i < pixels.size(); ++i) out[i] += static_cast<float>(pixels[i] * to_average);
}

NdfImage PositionNormalDistribution::image(const Footprint& footprint, const NdfGrid& grid,
                                           const ElementWindow* window) const {
  NdfImage img{grid, std::vector<float>(grid.pixel_count(), 0.0f)};
  accumulate_image(footprint, grid, 1.0, img.values.data(), window);
  return img;
}

NdfImage surface_ndf_histogram(const NormalMap& map, double intrinsic_roughness, const Footprint& footprint,
                               const NdfGrid& grid, std::uint64_t samples, std::uint32_t seed) {
  const NormalField field(map);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  // Cholesky factor of the footprint's covariance.
  const glm::dmat2& c = footprint.covariance;
  const double l00 = std::sqrt(std::max(c[0][0], 0.0));
  const double l10 = l00 > 0 ? c[0][1] / l00 : 0.0;
  const double l11 = std::sqrt(std::max(c[1][1] - l10 * l10, 0.0));
  std::vector<double> counts(grid.pixel_count(), 0.0);
  const int n = grid.resolution;
  for (std::uint64_t i = 0; i < samples; ++i) {
    const double z0 = normal(rng), z1 = normal(rng);
    const glm::dvec2 u = footprint.centre + glm::dvec2(l00 * z0, l10 * z0 + l11 * z1);
    const glm::dvec2 s = field.projected(u) + intrinsic_roughness * glm::dvec2(normal(rng), normal(rng));
    const glm::dvec2 p = grid.to_pixels(s);
    if (p.x < 0 || p.y < 0 || p.x >= n || p.y >= n) continue;
    counts[static_cast<std::size_t>(p.y) * n + static_cast<std::size_t>(p.x)] += 1.0;
  }
  NdfImage img{grid, std::vector<float>(grid.pixel_count())};
  const double to_average = 1.0 / (static_cast<double>(samples) * grid.pixel_area());
  for (std::size_t i = 0; i < counts.size(); ++i) img.values[i] = static_cast<float>(counts[i] * to_average);
  return img;
}

}  // namespace glintlab
