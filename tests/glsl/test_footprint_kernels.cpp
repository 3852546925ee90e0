// The footprint kernels of Kaplanyan et al. 2016 (shaders/lobe/footprint_filtering.glsl), on the
// GL device, against independent computations in C++: the pixel filter is a Gaussian of standard
// deviation kPixelFilterSigma = 0.5 px (the talk, "Filtering Beckmann"), and the bounding rectangle widens the lobe at
// least as much as the covariance along both slope axes (docs/methods.md#kaplanyan-rect).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/pixel_filter_width.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(
#include "lobe/footprint_filtering.glsl"
)";

double p22_beckmann(double x, double y, double ax, double ay) {
  return std::exp(-x * x / (ax * ax) - y * y / (ay * ay)) / (M_PI * ax * ay);
}

}  // namespace

TEST(FootprintKernels, KaplanyanBeckmannIsAHalfPixelGaussianPixelFilter) {
  // The filtered NDF must be the Beckmann P22 averaged over the pixel with a screen-space Gaussian
  // of sigma = kPixelFilterSigma = 0.5 px, mapped to slopes by the whole-pixel derivatives: h~(o) = h~ + U o. Summed on
  // a screen-space grid here, independently of C. (A sigma = 1 px filter is 4x too wide.)
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  struct Case {
    double ax, ay;
    glm::dvec2 dx, dy, slope;
  };
  std::vector<Case> cases;
  std::vector<glm::vec4> derivs, inputs;
  for (int i = 0; i < 16; ++i) {
    Case c;
    c.ax = 0.02 + 0.3 * u(rng);
    c.ay = c.ax * (0.5 + u(rng));
    c.dx = glm::dvec2(u(rng) - 0.5, u(rng) - 0.5) * (4.0 * c.ax);
    c.dy = glm::dvec2(u(rng) - 0.5, u(rng) - 0.5) * (4.0 * c.ax);
    c.slope = glm::dvec2(u(rng) - 0.5, u(rng) - 0.5) * (2.0 * c.ax);
    cases.push_back(c);
    derivs.emplace_back(c.dx.x, c.dx.y, c.dy.x, c.dy.y);
    inputs.emplace_back(c.ax, c.ay, c.slope.x, c.slope.y);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 d, vec4 p) {\n"
                                 "  Lobe l = kaplanyanBeckmannLobe(axisAlignedLobe(NDF_BECKMANN, p.xy), d.xy, d.zw, 100.0);\n"
                                 "  return vec4(slopeDensityBeckmann(p.zw, l.A)); }",
                                 derivs, inputs);
  const double sigma = kPixelFilterSigma;
  const int n = 240;
  const double step = 12.0 / n;  // standard normal z over |z| < 6, o = sigma z
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    double sum = 0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const double z1 = -6 + (a + 0.5) * step, z2 = -6 + (b + 0.5) * step;
        const glm::dvec2 t = sigma * (z1 * c.dx + z2 * c.dy);
        sum += std::exp(-0.5 * (z1 * z1 + z2 * z2)) / (2 * M_PI) *
               p22_beckmann(c.slope.x - t.x, c.slope.y - t.y, c.ax, c.ay);
      }
    const double expected = sum * step * step;
    EXPECT_NEAR(gpu[i].x, expected, 2e-3 * expected) << "case " << i;
  }
}

TEST(FootprintKernels, KaplanyanBeckmannEqualsTokuyoshisKernelOnBeckmann) {
  // Both are R' = R + 2 sigma^2 U U^T for a Gaussian pixel filter; tokuyoshi's default sigma2 = 0.25
  // (I3D 2019; kPixelFilterSigma^2) is the talk's 0.5 px, so on a Beckmann material (tokuyoshi adds
  // its kernel to alpha^2 directly) the two matrices agree for the same derivatives when neither
  // clamp acts.
  std::mt19937 rng(62);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 512; ++i) {
    const float alpha = std::pow(10.0f, -3.0f + 2.5f * (0.5f + 0.5f * u(rng)));
    const float scale = std::pow(10.0f, -3.0f + 2.5f * (0.5f + 0.5f * u(rng)));
    a.emplace_back(alpha, alpha * (1.0f + 0.5f * u(rng)), i % 3, 0.0f);
    b.emplace_back(u(rng) * scale, u(rng) * scale, u(rng) * scale, u(rng) * scale);
  }
  const std::string sigma2 = pixel_filter_variance_text();  // tokuyoshi's default
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 a, vec4 d) {\n"
                                 "  Lobe base = axisAlignedLobe(NDF_BECKMANN, a.xy);\n"
                                 "  Lobe k = kaplanyanBeckmannLobe(base, d.xy, d.zw, 100.0);\n"
                                 "  Lobe t = tokuyoshiLobe(base, d.xy, d.zw, " +
                                     sigma2 +
                                     ", 1e4);\n"
                                     "  mat2 e = k.A - t.A;\n"
                                     "  return vec4(e[0][0], e[1][1], e[0][1], k.A[0][0] + k.A[1][1]); }",
                                 a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double tol = 2e-6 * gpu[i].w;
    EXPECT_NEAR(gpu[i].x, 0.0, tol) << i;
    EXPECT_NEAR(gpu[i].y, 0.0, tol) << i;
    EXPECT_NEAR(gpu[i].z, 0.0, tol) << i;
  }
}

TEST(FootprintKernels, TheRectangleWidensAtLeastAsMuchAsTheCovarianceAlongTheSlopeAxes) {
  // For random footprints, with and without the fp_max clamps: the rectangle's lobe has per slope
  // axis at least the covariance's variance, hence (diagonal R) at least its determinant, hence a
  // peak density no higher; equal for axis-aligned footprints. Expected values from C++ with
  // sigma = 1/2: C = (U U^T) / 4, fp = (|dx| + |dy|) / 2.
  std::mt19937 rng(63);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 4096; ++i) {
    const float alpha = std::pow(10.0f, -3.0f + 3.0f * (0.5f + 0.5f * u(rng)));
    const float scale = std::pow(10.0f, -3.0f + 3.5f * (0.5f + 0.5f * u(rng)));
    const float fpMax = i % 2 ? 100.0f : 0.3f;
    glm::vec4 d(u(rng), u(rng), u(rng), u(rng));
    if (i % 8 == 1) d.y = d.z = 0.0f;  // axis-aligned footprint (unclamped: the clamps differ)
    a.emplace_back(alpha, alpha * (1.0f + 0.5f * u(rng)), fpMax, i % 8 == 1 ? 1.0f : 0.0f);
    b.push_back(d * scale);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 a, vec4 d) {\n"
                                 "  Lobe base = axisAlignedLobe(NDF_BECKMANN, a.xy);\n"
                                 "  Lobe c = kaplanyanBeckmannLobe(base, d.xy, d.zw, a.z);\n"
                                 "  Lobe r = kaplanyanRectLobe(base, d.xy, d.zw, a.z);\n"
                                 "  return vec4(r.A[0][0] - c.A[0][0], r.A[1][1] - c.A[1][1],\n"
                                 "              slopeDensityBeckmann(vec2(0.0), c.A), slopeDensityBeckmann(vec2(0.0), r.A)); }",
                                 a, b);
  int strict = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ax = a[i].x, ay = a[i].y, fpMax = a[i].z;
    const glm::dvec2 dx(b[i].x, b[i].y), dy(b[i].z, b[i].w);
    // Independent expectation of the rectangle's widening (per-axis clamp) and of the covariance's
    // diagonal (whole matrix scaled so that its largest eigenvalue is at most fp_max^2).
    const double fx = std::min(0.5 * (std::abs(dx.x) + std::abs(dy.x)), fpMax);
    const double fy = std::min(0.5 * (std::abs(dx.y) + std::abs(dy.y)), fpMax);
    double cxx = 0.25 * (dx.x * dx.x + dy.x * dy.x), cyy = 0.25 * (dx.y * dx.y + dy.y * dy.y);
    const double cxy = 0.25 * (dx.x * dx.y + dy.x * dy.y);
    const double top = 0.5 * (cxx + cyy) + std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
    if (top > fpMax * fpMax) cxx *= fpMax * fpMax / top, cyy *= fpMax * fpMax / top;
    const double scale = ax * ax + ay * ay + 2 * (fx * fx + fy * fy);
    const double tol = 2e-6 * scale;
    EXPECT_NEAR(gpu[i].x, 2 * (fx * fx - cxx), tol) << i;
    EXPECT_NEAR(gpu[i].y, 2 * (fy * fy - cyy), tol) << i;
    EXPECT_GE(gpu[i].x, -tol) << i;
    EXPECT_GE(gpu[i].y, -tol) << i;
    // Peak density 1 / (pi sqrt(det A')): the rectangle's is never higher.
    EXPECT_LE(gpu[i].w, gpu[i].z * (1 + 1e-5)) << i;
    if (a[i].w > 0.5f) {
      EXPECT_NEAR(gpu[i].w, gpu[i].z, 1e-5 * gpu[i].z) << "axis-aligned " << i;
    }
    if (gpu[i].w < gpu[i].z * 0.99) ++strict;
  }
  EXPECT_GT(strict, 100);  // the ordering is not vacuous
}

TEST(FootprintKernels, TheRectangleIsNotWiderInEveryDirection) {
  // The ordering above is not a matrix ordering (docs/methods.md#kaplanyan-rect): for a footprint
  // along the slope diagonal, dx = (L, L), dy = 0, the rectangle's variance along (1, 1)/sqrt(2) is
  // L^2/4, half the covariance's L^2/2.
  const float L = 0.1f;
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 a, vec4 d) {\n"
                                 "  Lobe base = axisAlignedLobe(NDF_BECKMANN, vec2(1e-4));\n"
                                 "  Lobe c = kaplanyanBeckmannLobe(base, d.xy, d.zw, 100.0);\n"
                                 "  Lobe r = kaplanyanRectLobe(base, d.xy, d.zw, 100.0);\n"
                                 "  vec2 e = vec2(0.70710678);\n"
                                 "  return vec4(dot(e, c.A * e), dot(e, r.A * e), 0.0, 0.0); }",
                                 {glm::vec4(0.0f)}, {glm::vec4(L, L, 0.0f, 0.0f)});
  EXPECT_NEAR(gpu[0].x, 2 * 0.5 * L * L, 1e-4 * L * L);   // 2 x variance L^2/2
  EXPECT_NEAR(gpu[0].y, 2 * 0.25 * L * L, 1e-4 * L * L);  // 2 x variance L^2/4
}
