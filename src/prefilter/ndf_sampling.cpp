#include "prefilter/ndf_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace glintlab {

namespace {

// Picks an index with probability masses[i] / sum, and rescales u into the chosen interval so that
// it can pick again (the hierarchical reuse of one uniform; double keeps ~40 bits through the
// handful of choices a sample makes).
int pick(const double* masses, int count, double& u) {
  double total = 0.0;
  for (int i = 0; i < count; ++i) total += std::max(masses[i], 0.0);
  if (!(total > 0.0)) return -1;
  double target = u * total, below = 0.0;
  int last = -1;
  for (int i = 0; i < count; ++i) {
    const double m = std::max(masses[i], 0.0);
    if (m <= 0.0) continue;
    last = i;
    if (target < below + m) {
      u = std::clamp((target - below) / m, 0.0, 1.0 - 1e-16);
      return i;
    }
    below += m;
  }
  u = 1.0 - 1e-16;  // u rounded past the last interval
  return last;
}

// The inverse CDF of the unit tent on [-1, 1].
double tent(double u) { return u < 0.5 ? std::sqrt(2.0 * u) - 1.0 : 1.0 - std::sqrt(2.0 * (1.0 - u)); }

}  // namespace

double prefiltered_ndf_mass(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma) {
  const double n = ndf.grid.resolution;
  double mass = 0.0;
  for (const auto& w : ndf.interpolation(centre, sigma))
    mass += w.weight * ndf.pixel_range_sum(w.footprint, {0.0, 0.0}, {n, n});
  return mass * ndf.grid.pixel_area();
}

double prefiltered_ndf_pdf(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma, glm::dvec2 s) {
  const double mass = prefiltered_ndf_mass(ndf, centre, sigma);
  return mass > 0.0 ? ndf.density(centre, sigma, s) / mass : 0.0;
}

std::optional<NdfSample> sample_prefiltered_ndf(const PrefilteredNdf& ndf, glm::dvec2 centre, double sigma,
                                                glm::dvec3 u) {
  const int n = ndf.grid.resolution, b = ndf.settings.block_size, blocks = ndf.blocks_per_side();
  double choice = u.x;
  // A stored footprint by its trilinear weight times its mass.
  const auto blend = ndf.interpolation(centre, sigma);
  std::vector<double> masses(blend.size());
  for (std::size_t i = 0; i < blend.size(); ++i)
    masses[i] = blend[i].weight * ndf.pixel_range_sum(blend[i].footprint, {0.0, 0.0}, {double(n), double(n)});
  double mass = 0.0;
  for (const double m : masses) mass += m;
  mass *= ndf.grid.pixel_area();
  const int f = pick(masses.data(), static_cast<int>(masses.size()), choice);
  if (f < 0) return std::nullopt;
  const std::uint32_t footprint = blend[static_cast<std::size_t>(f)].footprint;
  // A block by its range mass (dropped blocks have none).
  masses.assign(static_cast<std::size_t>(blocks * blocks), 0.0);
  for (int by = 0; by < blocks; ++by)
    for (int bx = 0; bx < blocks; ++bx)
      masses[static_cast<std::size_t>(by * blocks + bx)] =
          ndf.pixel_range_sum(footprint, glm::dvec2(bx, by) * double(b), glm::dvec2(bx + 1, by + 1) * double(b));
  const int block = pick(masses.data(), blocks * blocks, choice);
  if (block < 0) return std::nullopt;
  // Down a quadtree of the block's pixels: split each side longer than a pixel in two.
  glm::ivec2 lo = glm::ivec2(block % blocks, block / blocks) * b, hi = lo + b;
  while (hi.x - lo.x > 1 || hi.y - lo.y > 1) {
    const glm::ivec2 mid((lo.x + hi.x) / 2, (lo.y + hi.y) / 2);
    const glm::ivec2 splits(hi.x - lo.x > 1 ? 2 : 1, hi.y - lo.y > 1 ? 2 : 1);
    glm::ivec2 child_lo[4], child_hi[4];
    double child_mass[4] = {0.0, 0.0, 0.0, 0.0};
    int children = 0;
    for (int cy = 0; cy < splits.y; ++cy)
      for (int cx = 0; cx < splits.x; ++cx) {
        child_lo[children] = {splits.x == 1 ? lo.x : (cx == 0 ? lo.x : mid.x), splits.y == 1 ? lo.y : (cy == 0 ? lo.y : mid.y)};
        child_hi[children] = {splits.x == 1 ? hi.x : (cx == 0 ? mid.x : hi.x), splits.y == 1 ? hi.y : (cy == 0 ? mid.y : hi.y)};
        child_mass[children] = ndf.pixel_range_sum(footprint, glm::dvec2(child_lo[children]), glm::dvec2(child_hi[children]));
        ++children;
      }
    const int c = pick(child_mass, children, choice);
    if (c < 0) return std::nullopt;
    lo = child_lo[c];
    hi = child_hi[c];
  }
  // The pixel's centre plus a tent offset per axis: the bilinear interpolation's own kernel.
  const glm::dvec2 s = ndf.grid.pixel_centre(lo.x, lo.y) + ndf.grid.pixel_size() * glm::dvec2(tent(u.y), tent(u.z));
  const double pdf = ndf.density(centre, sigma, s) / mass;
  if (!(pdf > 0.0)) return std::nullopt;
  return NdfSample{s, pdf};
}

std::optional<NdfSample> sample_position_normal(const PositionNormalDistribution& pnd, const Footprint& footprint,
                                                glm::dvec3 u) {
  std::vector<PositionNormalDistribution::Term> terms;
  std::vector<double> weights;
  pnd.for_each_term(footprint, [&](const PositionNormalDistribution::Term& t) {
    terms.push_back(t);
    weights.push_back(t.weight);
  });
  double choice = u.x;
  const int e = pick(weights.data(), static_cast<int>(weights.size()), choice);
  if (e < 0) return std::nullopt;
  const PositionNormalDistribution::Term& t = terms[static_cast<std::size_t>(e)];
  // Box-Muller, then s = mean + L z with L L^T = covariance.
  const double radius = std::sqrt(-2.0 * std::log(1.0 - u.y)), angle = 6.283185307179586 * u.z;
  const glm::dvec2 z(radius * std::cos(angle), radius * std::sin(angle));
  const double l00 = std::sqrt(t.covariance[0][0]), l10 = t.covariance[0][1] / l00;
  const double l11 = std::sqrt(std::max(t.covariance[1][1] - l10 * l10, 0.0));
  const glm::dvec2 s = t.mean + glm::dvec2(l00 * z.x, l10 * z.x + l11 * z.y);
  const double pdf = pnd.density(footprint, s);
  if (!(pdf > 0.0)) return std::nullopt;
  return NdfSample{s, pdf};
}

}  // namespace glintlab
