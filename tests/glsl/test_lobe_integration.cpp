// Lobe integrals of shaders/lobe/lobe.glsl on the GL device against adaptive quadrature in
// double precision: box averages of GGX from 0.1 to 1000 alphas wide (issue 11, item 5) and the
// lobe's mass over a light's image (item 7).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = "#include \"lobe/light_image.glsl\"\n";

/// Adaptive Simpson quadrature of f over [a, b] to absolute tolerance eps.
double simpson(const std::function<double(double)>& f, double a, double b, double eps) {
  std::function<double(double, double, double, double, double, double, double, int)> rec =
      [&](double lo, double hi, double flo, double fmid, double fhi, double whole, double tol, int d) {
        const double mid = 0.5 * (lo + hi), fl = f(0.5 * (lo + mid)), fr = f(0.5 * (mid + hi));
        const double left = (mid - lo) / 6 * (flo + 4 * fl + fmid), right = (hi - mid) / 6 * (fmid + 4 * fr + fhi);
        if (d > 45 || std::abs(left + right - whole) < 15 * tol) return left + right + (left + right - whole) / 15;
        return rec(lo, mid, flo, fl, fmid, left, 0.5 * tol, d + 1) + rec(mid, hi, fmid, fr, fhi, right, 0.5 * tol, d + 1);
      };
  const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
  return rec(a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), eps, 0);
}

/// The same over [a, b] split at the points where an alpha-unit density changes scale
/// (0, +-1, +-10, +-100), so that a peak inside a wide interval is not stepped over.
double split_simpson(const std::function<double(double)>& f, double a, double b, double eps) {
  std::vector<double> cuts = {a};
  for (double c : {-100.0, -10.0, -1.0, 0.0, 1.0, 10.0, 100.0})
    if (c > a && c < b) cuts.push_back(c);
  cuts.push_back(b);
  double sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) sum += simpson(f, cuts[i], cuts[i + 1], eps / double(cuts.size()));
  return sum;
}

double ggx(double u, double v) {
  const double e = 1 + u * u + v * v;
  return 1 / (M_PI * e * e);
}
double beckmann(double u, double v) { return std::exp(-u * u - v * v) / M_PI; }

/// Mass of a unit-alpha density over [x0, x1] x [y0, y1], to about 1e-7 relative.
double box_mass(const std::function<double(double, double)>& p, double x0, double x1, double y0, double y1) {
  auto pass = [&](double eps) {
    return split_simpson([&](double x) { return split_simpson([&](double y) { return p(x, y); }, y0, y1, eps); }, x0, x1,
                         eps * (x1 - x0 + 1));
  };
  const double rough = pass(1e-6 * p(std::clamp(0.0, x0, x1), std::clamp(0.0, y0, y1)));
  return pass(1e-8 * rough / std::max(1.0, x1 - x0));
}

}  // namespace

TEST(LobeIntegration, GgxBoxAverageHoldsFromATenthToAThousandAlphas) {
  // Boxes 0.1 to 1000 alphas wide (each side from the list, the other side a different width),
  // on the peak, holding it off-centre, touching it, and 1, 10 and 100 alphas away; alpha in
  // slope units from 0.002 to 0.5. The case: a +-60 alpha box on the peak.
  const std::vector<double> widths = {0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000};
  struct Case {
    glm::dvec2 c, h;
    double alpha;
  };
  std::vector<Case> cases;
  for (std::size_t i = 0; i < widths.size(); ++i) {
    const glm::dvec2 h(0.5 * widths[i], 0.5 * widths[(i + 4) % widths.size()]);
    const double alpha = std::vector<double>{0.002, 0.05, 0.5}[i % 3];
    for (const glm::dvec2& c : {glm::dvec2(0), 0.3 * h * glm::dvec2(1, -1), h, h + glm::dvec2(1, 0),
                                h + glm::dvec2(10, 10), h + glm::dvec2(100, -2 * h.y)})
      cases.push_back({c, h, alpha});
  }
  cases.push_back({glm::dvec2(0), glm::dvec2(60), 0.002});
  std::vector<glm::vec4> boxes, params;
  for (const auto& k : cases) {
    boxes.emplace_back(k.c.x * k.alpha, k.c.y * k.alpha, k.h.x * k.alpha, k.h.y * k.alpha);
    params.emplace_back(k.alpha, k.alpha, 0, 0);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 box, vec4 p) {\n"
                                 "  return vec4(boxAveragedSlopeDensity(NDF_GGX, box.xy, box.zw, p.xy)); }",
                                 boxes, params);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& k = cases[i];
    const double mass = box_mass(ggx, k.c.x - k.h.x, k.c.x + k.h.x, k.c.y - k.h.y, k.c.y + k.h.y);
    const double expected = mass / (4 * k.h.x * k.h.y) / (k.alpha * k.alpha);
    EXPECT_NEAR(gpu[i].x / expected, 1.0, 2e-3) << "box " << k.c.x << ", " << k.c.y << " +- " << k.h.x << ", " << k.h.y
                                                 << " alphas (alpha " << k.alpha << "): " << gpu[i].x << " vs " << expected;
  }
}

TEST(LobeIntegration, BeckmannBoxAverageHoldsWideBoxes) {
  // Beckmann's separable erf form for boxes up to 1000 alphas wide that hold most of the lobe.
  std::vector<glm::dvec4> cases;
  for (double w : {0.1, 1.0, 10.0, 100.0, 1000.0})
    for (double offset : {0.0, 0.4, 1.0}) cases.emplace_back(offset * 0.5 * w, 0.2, 0.5 * w, 0.5 * std::max(1.0, w / 10));
  std::vector<glm::vec4> boxes, params;
  for (const auto& k : cases) {
    boxes.emplace_back(k * 0.1);
    params.emplace_back(0.1f, 0.1f, 0, 0);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 box, vec4 p) {\n"
                                 "  return vec4(boxAveragedSlopeDensity(NDF_BECKMANN, box.xy, box.zw, p.xy)); }",
                                 boxes, params);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& k = cases[i];
    const double expected = box_mass(beckmann, k.x - k.z, k.x + k.z, k.y - k.w, k.y + k.w) / (4 * k.z * k.w) / 0.01;
    EXPECT_NEAR(gpu[i].x / expected, 1.0, 2e-3) << "box " << k.x << ", " << k.y << " +- " << k.z << ", " << k.w;
  }
}

TEST(LobeIntegration, GgxDiskMassMatchesQuadrature) {
  // Mass of the unit GGX density in a disk of radius r at distance d, against adaptive
  // quadrature in polar coordinates about the disk's centre: from disks far smaller than the
  // lobe to 1000 times larger, on the peak, across it and far in the tails.
  std::vector<glm::vec4> in, unused;
  std::vector<double> expected;
  for (double r : {1e-3, 0.1, 1.0, 10.0, 1000.0})
    for (double d : {0.0, 0.5 * r, r - 0.5, r, r + 1.0, 3.0 * r + 2.0, 100.0 * r + 50.0}) {
      if (d < 0) continue;
      in.emplace_back(d, r, 0, 0);
      unused.emplace_back(0);
      const double mass = simpson(
          [&](double q) {
            return q * simpson([&](double phi) { return ggx(d + q * std::cos(phi), q * std::sin(phi)); }, 0, M_PI,
                               1e-12 * ggx(std::max(d - q, 0.0), 0));
          },
          0, r, 1e-12 * ggx(std::max(d - r, 0.0), 0) * r * r);
      expected.push_back(2 * mass);
    }
  const auto gpu = evaluate_glsl(kIncludes, "vec4 evaluate(vec4 a, vec4 b) { return vec4(ggxDiskMass(a.x, a.y)); }", in, unused);
  for (std::size_t i = 0; i < in.size(); ++i)
    EXPECT_NEAR(gpu[i].x / expected[i], 1.0, 1e-3) << "d " << in[i].x << " r " << in[i].y << ": " << gpu[i].x << " vs "
                                                   << expected[i];
}

TEST(LobeIntegration, MassOnImageLimitsAndEnergy) {
  // lobeMassOnImage for GGX lobes and an elliptic image c + J x, |x| <= 1 (slope units):
  // (1) a light far smaller than the lobe gives P22(c) x area; (2) a lobe far narrower than the
  // image gives the ellipse's indicator (the mirror), along its long and short axes; (3) summed
  // over image positions, the mass is the image's area for every lobe (convolution keeps energy),
  // for matrix lobes and for a box-averaged lobe.
  const glm::dmat2 J(glm::dvec2(0.02, 0.006), glm::dvec2(-0.003, 0.01));
  const double area = M_PI * std::abs(glm::determinant(J));
  const std::string body =
      "vec4 evaluate(vec4 a, vec4 b) {\n"
      "  Lobe lobe = Lobe(NDF_GGX, mat2(a.z * a.z, 0.0, 0.0, a.z * a.z), vec2(a.w, 2.0 * a.w));\n"
      "  return vec4(lobeMassOnImage(lobe, LightImage(a.xy, mat2(0.02, 0.006, -0.003, 0.01) * b.x))); }";
  // (1) and (2).
  std::vector<glm::vec4> a, b;
  std::vector<double> expected, tolerance;
  for (const glm::dvec2& c : {glm::dvec2(0), glm::dvec2(0.1, -0.05), glm::dvec2(0.4, 0.3)}) {
    a.emplace_back(c.x, c.y, 0.3, 0);
    b.emplace_back(1e-3, 0, 0, 0);
    const double e = 1 + glm::dot(c, c) / 0.09;
    expected.push_back(area * 1e-6 / (M_PI * 0.09 * e * e));
    tolerance.push_back(2e-3 * expected.back());
  }
  for (double radius : {0.5, 0.9, 1.1, 2.0})
    for (const glm::dvec2& x : {glm::dvec2(1, 0), glm::dvec2(0, 1), glm::normalize(glm::dvec2(1, -1))}) {
      const glm::dvec2 c = -(J * (radius * x));  // the peak (origin) at c + J (radius x)
      a.emplace_back(c.x, c.y, 1e-4, 0);
      b.emplace_back(1, 0, 0, 0);
      expected.push_back(radius < 1 ? 1.0 : 0.0);
      tolerance.push_back(0.02);
    }
  auto gpu = evaluate_glsl(kIncludes, body, a, b);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(gpu[i].x, expected[i], tolerance[i]) << "centre " << a[i].x << ", " << a[i].y << " alpha " << a[i].z;
  // (3) Riemann sums over a grid of image centres.
  for (const glm::vec2 lobe : {glm::vec2(1e-3f, 0), glm::vec2(0.01f, 0), glm::vec2(0.05f, 0), glm::vec2(0.01f, 0.01f)}) {
    const double half = 0.03 + 20 * lobe.x + 4 * lobe.y;
    const int n = 256;
    const double cell = 2 * half / n;
    a.clear();
    b.clear();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        a.emplace_back(-half + (i + 0.5) * cell, -half + (j + 0.5) * cell, lobe.x, lobe.y);
        b.emplace_back(1, 0, 0, 0);
      }
    gpu = evaluate_glsl(kIncludes, body, a, b);
    double sum = 0;
    for (const auto& v : gpu) sum += v.x * cell * cell;
    EXPECT_NEAR(sum / area, 1.0, 0.02) << "alpha " << lobe.x << " footprint " << lobe.y;
  }
}
