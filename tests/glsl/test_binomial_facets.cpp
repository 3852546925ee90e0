// The raster-facets reference's surface (shaders/glints/binomial/facets.glsl; docs/methods.md,
// "A surface of facets") on the GL device against truths computed here: the facets' slopes follow
// the GGX slope density (chi-square, and their neighbours' independent of them), and the facets of
// a region that reflect a delta light are a binomial count with the probability of a quadrature of
// P22 over the reflecting disk, their mean the smooth BRDF.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(#include "glints/binomial/facets.glsl"
)";

// e^(log_density / 2) = 256 cells per unit of uv.
const double kLogDensity = 2.0 * std::log(256.0);
constexpr int kCells = 256;

// The GGX slope CDF in units of alpha, q^2 / (1 + q^2): the radial octile of a unit slope.
int radial_octile(glm::vec2 u) {
  const double q2 = double(u.x) * u.x + double(u.y) * u.y;
  return std::min(7, static_cast<int>(8.0 * q2 / (1.0 + q2)));
}

int angular_octile(glm::vec2 u) {
  const double phi = std::atan2(double(u.y), double(u.x)) + M_PI;
  return std::min(7, static_cast<int>(8.0 * phi / (2.0 * M_PI)));
}

double chi_square(const std::vector<double>& counts, double expected) {
  double chi2 = 0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

// Every cell's facet: (unit slope, normal.z, the slope's x over alpha recovered from the normal).
std::vector<glm::vec4> facets(glm::vec2 alpha) {
  std::vector<glm::vec4> a;
  for (int y = 0; y < kCells; ++y)
    for (int x = 0; x < kCells; ++x)
      a.emplace_back((x + 0.5f) / kCells, (y + 0.5f) / kCells, alpha.x, alpha.y);
  return evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  BinomialFacet f = binomialFacetAt(a.xy, b.x, a.zw, 0.01);
  return vec4(f.unitSlope, f.normal.z, -f.normal.x / f.normal.z / a.z);
})", a, std::vector<glm::vec4>(a.size(), glm::vec4(float(kLogDensity), 0, 0, 0)));
}

}  // namespace

TEST(BinomialFacets, SlopesFollowTheGgxDensityIndependentlyOfTheirNeighbours) {
  const auto r = facets({0.3f, 0.1f});
  const double n = double(r.size());
  // 64 cells of equal GGX mass: 8 radial octiles of the slope CDF by 8 angular octiles.
  std::vector<double> cells(64, 0.0), wrong(64, 0.0), pairs(64, 0.0);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const glm::vec2 u(r[i].x, r[i].y);
    cells[radial_octile(u) * 8 + angular_octile(u)] += 1;
    wrong[radial_octile(1.1f * u) * 8 + angular_octile(u)] += 1;  // 10% too wide: must fail
    // The facet's normal is its slope's: slope = -m.xy / m.z, in units of alpha.
    ASSERT_NEAR(r[i].w, u.x, 1e-3 * (1.0 + std::abs(u.x))) << "cell " << i;
    // The next cell along x: independent, so each pair of radial octiles is 1/64 of the pairs.
    if ((i + 1) % kCells) pairs[radial_octile(u) * 8 + radial_octile({r[i + 1].x, r[i + 1].y})] += 1;
  }
  const double pair_count = n - kCells;
  // chi-square with 63 degrees of freedom: 103.4 at p = 0.001.
  const double chi2 = chi_square(cells, n / 64), chi2_wrong = chi_square(wrong, n / 64),
               chi2_pairs = chi_square(pairs, pair_count / 64);
  std::printf("facet slopes: chi-square %.1f (a 10%% wider law %.1f), neighbour pairs %.1f; 63 dof\n", chi2, chi2_wrong,
              chi2_pairs);
  EXPECT_LT(chi2, 103.4);
  EXPECT_LT(chi2_pairs, 103.4);
  EXPECT_GT(chi2_wrong, 103.4 * 3);
}

TEST(BinomialFacets, ADeltaLightReflectsOffABinomialCountWhoseMeanIsTheSmoothBrdf) {
  // One view and one light for every cell: h = normalize(wo + wi) at about 0.8 alpha from the
  // peak; R sets the reflecting disk's radius sqrt(R) / h.z^2 in units of alpha.
  const glm::vec2 alpha(0.25f, 0.25f);
  const float R = 0.1f;
  const glm::dvec3 wo = glm::normalize(glm::dvec3(0.3, 0.1, 1.0)), wi = glm::normalize(glm::dvec3(-0.5, 0.05, 1.0));
  std::vector<glm::vec4> a;
  for (int y = 0; y < kCells; ++y)
    for (int x = 0; x < kCells; ++x) a.emplace_back((x + 0.5f) / kCells, (y + 0.5f) / kCells, float(kLogDensity), R);
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec2 alpha = vec2(0.25);
  BinomialFacet f = binomialFacetAt(a.xy, a.z, alpha, a.w);
  vec3 wo = normalize(vec3(0.3, 0.1, 1.0)), wi = normalize(vec3(-0.5, 0.05, 1.0));  // as in the test
  return vec4(binomialFacetDeltaSpecularCos(f, wo, wi, vec3(1.0), alpha).x, specularCos(NDF_GGX, wo, wi, alpha, vec3(1.0)).x, 0.0, 0.0);
})", a, std::vector<glm::vec4>(a.size()));

  // The reflecting disk's mass under P22 (units of alpha: 1 / (pi (1 + |u|^2)^2)) by quadrature.
  const glm::dvec3 h = glm::normalize(wo + wi);
  const glm::dvec2 centre = -glm::dvec2(h.x, h.y) / (h.z * double(alpha.x));
  const double radius = std::sqrt(double(R)) / (h.z * h.z);
  double p = 0;
  const int nr = 400, nphi = 400;
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nphi; ++j) {
      const double rho = (i + 0.5) / nr * radius, phi = (j + 0.5) / nphi * 2 * M_PI;
      const glm::dvec2 u = centre + rho * glm::dvec2(std::cos(phi), std::sin(phi));
      const double d = 1.0 + glm::dot(u, u);
      p += rho / (M_PI * d * d) * (radius / nr) * (2 * M_PI / nphi);
    }

  // 4 x 4 blocks of cells: the number of reflecting facets in each against Binomial(16, p).
  constexpr int kBlock = 4, kN = kBlock * kBlock;
  std::vector<double> histogram(kN + 1, 0.0);
  double value_sum = 0;
  for (int by = 0; by < kCells; by += kBlock)
    for (int bx = 0; bx < kCells; bx += kBlock) {
      int k = 0;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) {
          const float v = r[static_cast<std::size_t>(y) * kCells + x].x;
          ASSERT_TRUE(std::isfinite(v));
          k += v > 0;
          value_sum += v;
        }
      histogram[k] += 1;
    }
  const double blocks = double(kCells / kBlock) * (kCells / kBlock);
  // Pool the tail so that every bin expects at least 5 blocks.
  double chi2 = 0, tail_seen = 0, tail_expected = 0;
  int bins = 0;
  for (int k = 0; k <= kN; ++k) {
    const double expected = blocks * std::exp(std::lgamma(kN + 1.0) - std::lgamma(k + 1.0) - std::lgamma(kN - k + 1.0) +
                                              k * std::log(p) + (kN - k) * std::log1p(-p));
    if (expected >= 5 && tail_expected == 0) {
      chi2 += (histogram[k] - expected) * (histogram[k] - expected) / expected;
      ++bins;
    } else {
      tail_seen += histogram[k];
      tail_expected += expected;
    }
  }
  if (tail_expected > 0) {
    chi2 += (tail_seen - tail_expected) * (tail_seen - tail_expected) / tail_expected;
    ++bins;
  }
  const double smooth = r[0].y, mean = value_sum / r.size();
  // The mean's standard error: each value is smooth / p with probability p.
  const double se = smooth / p * std::sqrt(p * (1 - p) / r.size());
  std::printf("delta light: p %.4f, reflecting share %.4f; count chi-square %.1f over %d bins; mean / smooth %.4f "
              "+- %.4f\n",
              p, mean / smooth * p, chi2, bins, mean / smooth, se / smooth);
  ASSERT_GT(p, 0.05);  // the test's geometry: a count with several bins
  // chi-square, bins - 1 degrees of freedom (at most 10 here): below its p = 0.001 point, 29.6.
  EXPECT_LT(chi2, 29.6);
  EXPECT_NEAR(mean, smooth, 4 * se);
}
