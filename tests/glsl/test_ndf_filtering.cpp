// The NDF-filtering functions of the specular anti-aliasing family (shaders/lobe/lobe.glsl,
// footprint_filtering.glsl, roughness_filtering.glsl), evaluated on the GL device and compared
// with independent computations in C++: quadrature, numerical convolution, CPU moments.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "gl_fixture.hpp"
#include "test_scenes.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(
#include "lobe/footprint_filtering.glsl"
#include "lobe/roughness_filtering.glsl"
#include "lobe/light_image.glsl"
)";

/// Adaptive Simpson quadrature of f over [a, b] to absolute tolerance eps.
double simpson(const std::function<double(double)>& f, double a, double b, double eps, int depth = 0) {
  const double m = 0.5 * (a + b), fa = f(a), fm = f(m), fb = f(b);
  std::function<double(double, double, double, double, double, double, int)> rec =
      [&](double lo, double hi, double flo, double fmid, double fhi, double whole, int d) {
        const double mid = 0.5 * (lo + hi), l = 0.5 * (lo + mid), r = 0.5 * (mid + hi);
        const double fl = f(l), fr = f(r);
        const double left = (mid - lo) / 6 * (flo + 4 * fl + fmid), right = (hi - mid) / 6 * (fmid + 4 * fr + fhi);
        if (d > 40 || std::abs(left + right - whole) < 15 * eps) return left + right + (left + right - whole) / 15;
        return rec(lo, mid, flo, fl, fmid, left, d + 1) + rec(mid, hi, fmid, fr, fhi, right, d + 1);
      };
  return rec(a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), depth);
}

/// Slope densities P22 (unit integral over the slope plane) for diagonal roughness.
double p22_ggx(double x, double y, double ax, double ay) {
  const double e = 1 + x * x / (ax * ax) + y * y / (ay * ay);
  return 1 / (M_PI * ax * ay * e * e);
}
double p22_beckmann(double x, double y, double ax, double ay) {
  return std::exp(-x * x / (ax * ax) - y * y / (ay * ay)) / (M_PI * ax * ay);
}

}  // namespace

TEST(NdfFiltering, BoxAveragedSlopeDensityMatchesQuadrature) {
  // Rectangles from 5% of alpha to several alphas wide, centred up to 3 alphas from the peak (so
  // many cross zero), anisotropic alpha; GGX (closed form with arctangents) and Beckmann (erf).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec4> boxes, params;
  for (int i = 0; i < 120; ++i) {
    const double ax = std::exp(std::log(0.01) + u(rng) * std::log(100.0));
    const double ay = ax * std::exp((u(rng) - 0.5) * std::log(16.0));
    const double hx = ax * std::exp(std::log(0.05) + u(rng) * std::log(80.0));
    const double hy = ay * std::exp(std::log(0.05) + u(rng) * std::log(80.0));
    boxes.emplace_back((u(rng) - 0.5) * 6 * ax, (u(rng) - 0.5) * 6 * ay, hx, hy);
    params.emplace_back(ax, ay, static_cast<float>(i % 2), 0.0f);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 box, vec4 p) {\n"
                                 "  return vec4(boxAveragedSlopeDensity(int(p.z), box.xy, box.zw, p.xy)); }",
                                 boxes, params);
  double worst = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const glm::dvec4 b(boxes[i]);
    const double ax = params[i].x, ay = params[i].y;
    const bool beckmann = params[i].z > 0.5f;
    auto density = [&](double x, double y) { return beckmann ? p22_beckmann(x, y, ax, ay) : p22_ggx(x, y, ax, ay); };
    const double peak = density(0, 0);
    const double mass = simpson(
        [&](double x) { return simpson([&](double y) { return density(x, y); }, b.y - b.w, b.y + b.w, 1e-11 * peak); },
        b.x - b.z, b.x + b.z, 1e-10 * peak * b.w);
    const double expected = mass / (4 * b.z * b.w);
    const double err = std::abs(gpu[i].x - expected) / expected;
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-3) << (beckmann ? "Beckmann" : "GGX") << " box " << b.x << "," << b.y << " +- " << b.z << ","
                         << b.w << " alpha " << ax << "," << ay << ": " << gpu[i].x << " vs " << expected;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(NdfFiltering, PeakBoxAverageMatchesQuadrature) {
  // The box lobe's peak density (the LTC's stand-in for box lobes): boxes centred on the peak from
  // a thousandth of alpha (the 1/pi limit, where a difference of quadrant masses would cancel) to
  // a hundred alphas, anisotropic alpha, GGX.
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec4> boxes, params;
  for (int i = 0; i < 60; ++i) {
    const double ax = std::exp(std::log(0.01) + u(rng) * std::log(100.0));
    const double ay = ax * std::exp((u(rng) - 0.5) * std::log(16.0));
    const double hx = ax * std::exp(std::log(1e-3) + u(rng) * std::log(1e5));
    const double hy = ay * std::exp(std::log(1e-3) + u(rng) * std::log(1e5));
    boxes.emplace_back(0.0f, 0.0f, hx, hy);
    params.emplace_back(ax, ay, 0.0f, 0.0f);
  }
  const auto gpu = evaluate_glsl(kIncludes,
                                 "vec4 evaluate(vec4 box, vec4 p) {\n"
                                 "  return vec4(peakBoxAveragedSlopeDensity(NDF_GGX, box.zw, p.xy)); }",
                                 boxes, params);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const double hx = boxes[i].z, hy = boxes[i].w, ax = params[i].x, ay = params[i].y;
    const double peak = p22_ggx(0, 0, ax, ay);
    const double quadrant = simpson(
        [&](double x) { return simpson([&](double y) { return p22_ggx(x, y, ax, ay); }, 0, hy, 1e-12 * peak); }, 0,
        hx, 1e-11 * peak * hy);
    const double expected = quadrant / (hx * hy);
    EXPECT_NEAR(gpu[i].x / expected, 1.0, 1e-4) << "box +- " << hx << "," << hy << " alpha " << ax << "," << ay;
  }
}

// Kaplanyan's Beckmann kernel against a numerical convolution: tests/glsl/test_footprint_kernels.cpp.

TEST(NdfFiltering, LeanCovarianceMatchesCpuMoments) {
  // The slope-moment textures, mipmapped by the GL, sampled at texel centres of level L, give
  // the covariance of the slopes of the 2^L x 2^L texels under each coarse texel.
  SceneFixture f(TestScene::minimal().material(
      "bumpy", {{"alpha", 0.1},
                {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.4}, {"waves", 24},
                                        {"max_frequency", 6}, {"seed", 3}}}}));
  const int material = 1;
  const NormalMap& map = *f.scene.materials[material].normal_map;
  ASSERT_EQ(map.width, 64);
  glBindTextureUnit(1, f.gpu->slope_moments(material));
  glBindTextureUnit(2, f.gpu->slope_cross_moment(material));
  std::vector<glm::vec4> where, unused;
  struct Expected {
    glm::dvec2 b;
    glm::dvec3 sigma;
  };
  std::vector<Expected> expected;
  for (int level : {0, 2, 4})
    for (int t = 0; t < 6; ++t) {
      const int size = map.width >> level, block = 1 << level;
      const int tx = (t * 7 + level) % size, ty = (t * 5 + 2 * level) % size;
      glm::dvec2 b(0);
      glm::dvec3 m(0);
      for (int y = ty * block; y < (ty + 1) * block; ++y)
        for (int x = tx * block; x < (tx + 1) * block; ++x) {
          const glm::dvec3 n(map.normals[static_cast<std::size_t>(y * map.width + x)]);
          const glm::dvec2 s(n.x / n.z, n.y / n.z);
          b += s;
          m += glm::dvec3(s.x * s.x, s.y * s.y, s.x * s.y);
        }
      b /= block * block;
      m /= block * block;
      expected.push_back({b, glm::dvec3(m.x - b.x * b.x, m.y - b.y * b.y, m.z - b.x * b.y)});
      where.emplace_back((tx + 0.5) / size, (ty + 0.5) / size, level, 0);
      unused.emplace_back(0);
    }
  const auto gpu = evaluate_glsl(std::string(kIncludes) + R"(
layout(binding = 1) uniform sampler2D uSlopeMoments;
layout(binding = 2) uniform sampler2D uSlopeCrossMoment;
)",
                                 "vec4 evaluate(vec4 w, vec4 unused) {\n"
                                 "  vec4 m = textureLod(uSlopeMoments, w.xy, w.z);\n"
                                 "  mat2 s = leanSlopeCovariance(m.xy, vec3(m.zw, textureLod(uSlopeCrossMoment, w.xy, w.z).r));\n"
                                 "  return vec4(s[0][0], s[1][1], s[0][1], m.x); }",
                                 where, unused);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& e = expected[i];
    const double scale = 1e-4 + e.sigma.x + e.sigma.y;
    EXPECT_NEAR(gpu[i].x, e.sigma.x, 1e-4 * scale + 1e-6) << i;
    EXPECT_NEAR(gpu[i].y, e.sigma.y, 1e-4 * scale + 1e-6) << i;
    EXPECT_NEAR(gpu[i].z, e.sigma.z, 1e-4 * scale + 1e-6) << i;
    EXPECT_NEAR(gpu[i].w, e.b.x, 1e-5) << i;
  }
}

namespace {

// Every filter applied to one (alpha, footprint) input: returns the four entries of interest
// for the filter selected by p.w (0..5): A_xx, A_yy, A_xy, box half side x.
const char* kEveryFilter = R"(
vec4 applyFilter(int which, int ndf, vec2 alpha, vec2 dx, vec2 dy, vec3 dn) {
  Lobe base = axisAlignedLobe(ndf, alpha);
  Lobe l = base;
  if (which == 0) l = kaplanyanBeckmannLobe(base, dx, dy, 1.0);
  if (which == 1) l = kaplanyanRectLobe(base, dx, dy, 1.0);
  if (which == 2) l = kaplanyanBoxLobe(base, dx, dy, 1.0);
  if (which == 3) l = tokuyoshiLobe(base, dx, dy, 0.25, 0.18);
  if (which == 4) { vec2 a = vlachosAlpha(alpha, dn, dn.yzx, 1.0, 1.0 / 3.0); l = axisAlignedLobe(ndf, a); }
  if (which == 5) { vec2 a = toksvigAlpha(alpha, 1.0 - abs(dn.x), 1.0); l = axisAlignedLobe(ndf, a); }
  if (which == 6) l.A += 2.0 * leanSlopeCovariance(dx, vec3(dy, dn.x));
  return vec4(l.A[0][0], l.A[1][1], l.A[0][1], l.footprint.x);
}
)";
constexpr int kFilterCount = 7;
const char* kFilterNames[kFilterCount] = {"kaplanyan-beckmann", "kaplanyan-rect", "kaplanyan-ggx", "tokuyoshi",
                                          "vlachos",            "toksvig",        "lean"};

}  // namespace

TEST(NdfFiltering, ZeroFootprintLeavesTheLobeUnchanged) {
  std::vector<glm::vec4> a, b;
  for (int which = 0; which < kFilterCount; ++which)
    for (float alpha : {1e-4f, 0.002f, 0.05f, 0.3f, 0.9f})
      for (int ndf : {0, 1}) {
        a.emplace_back(alpha, alpha * 0.5f + 1e-4f, ndf, which);
        b.emplace_back(0.0f);
      }
  const auto gpu = evaluate_glsl(std::string(kIncludes) + kEveryFilter,
                                 "vec4 evaluate(vec4 a, vec4 b) {\n"
                                 "  return applyFilter(int(a.w), int(a.z), a.xy, vec2(0.0), vec2(0.0), vec3(0.0)); }",
                                 a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ax = std::max(a[i].x, 1e-4f), ay = std::max(a[i].y, 1e-4f);
    const std::string what = std::string(kFilterNames[static_cast<int>(a[i].w)]) + " alpha " + std::to_string(ax);
    EXPECT_NEAR(gpu[i].x, ax * ax, 2e-6 * ax * ax) << what;
    EXPECT_NEAR(gpu[i].y, ay * ay, 2e-6 * ay * ay) << what;
    EXPECT_EQ(gpu[i].z, 0.0f) << what;
    EXPECT_EQ(gpu[i].w, 0.0f) << what;
  }
}

TEST(NdfFiltering, FilteringNeverSharpensTheLobe) {
  // A' - A is positive semi-definite (and the box only grows) for random footprints.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 4000; ++i) {
    const float alpha = std::pow(10.0f, -4.0f + 4.0f * (0.5f + 0.5f * u(rng)));
    const float scale = std::pow(10.0f, 3.0f * u(rng));
    a.emplace_back(alpha, std::min(1.0f, alpha * (1.0f + 0.5f * u(rng))), i % 2, i % kFilterCount);
    b.emplace_back(u(rng) * scale, u(rng) * scale, u(rng) * scale, u(rng) * scale);
  }
  const auto gpu = evaluate_glsl(std::string(kIncludes) + kEveryFilter,
                                 "vec4 evaluate(vec4 a, vec4 b) {\n"
                                 "  vec3 m = vec3(b.z * b.z + abs(b.x), b.w * b.w + abs(b.y), b.z * b.w);  // valid moments\n"
                                 "  return int(a.w) == 6 ? applyFilter(6, int(a.z), a.xy, b.xy, m.xy, vec3(m.z + b.x * b.y, 0.0, 0.0))\n"
                                 "                       : applyFilter(int(a.w), int(a.z), a.xy, b.xy, b.zw, vec3(b.xyz) * 1e-3); }",
                                 a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ax = std::max(a[i].x, 1e-4f), ay = std::max(a[i].y, 1e-4f);
    const double dxx = gpu[i].x - ax * ax, dyy = gpu[i].y - ay * ay, dxy = gpu[i].z;
    const double tol = 1e-6 * (ax * ax + ay * ay + std::abs(gpu[i].x) + std::abs(gpu[i].y));
    const std::string what = kFilterNames[static_cast<int>(a[i].w)];
    EXPECT_GE(dxx, -tol) << what << " " << i;
    EXPECT_GE(dyy, -tol) << what << " " << i;
    EXPECT_GE(dxx * dyy - dxy * dxy, -tol * (std::abs(dxx) + std::abs(dyy) + tol)) << what << " " << i;
    EXPECT_GE(gpu[i].w, 0.0f) << what;
  }
}

TEST(NdfFiltering, FilteredNdfsIntegrateToOneOverTheProjectedHemisphere) {
  // Integral of D(h) cos(theta_h) over the hemisphere for matrix lobes (random rotation and
  // anisotropy) and box-averaged lobes, by quadrature in (r = tan theta, phi) with
  // d(omega) cos(theta) = cos^4(theta) r dr dphi, r = s u / (1 - u) to reach the tails.
  struct LobeCase {
    glm::vec4 a;  // A_xx, A_yy, A_xy, ndf
    glm::vec2 box;
  };
  const std::vector<LobeCase> lobes = {
      {{0.04f, 0.09f, 0.03f, 0}, {0, 0}},   {{0.04f, 0.09f, 0.03f, 1}, {0, 0}},
      {{0.5f, 0.1f, -0.15f, 0}, {0, 0}},    {{0.5f, 0.1f, -0.15f, 1}, {0, 0}},
      {{0.01f, 0.04f, 0.0f, 0}, {0.3f, 0.1f}}, {{0.01f, 0.04f, 0.0f, 1}, {0.3f, 0.1f}},
      {{0.25f, 0.25f, 0.0f, 0}, {0.05f, 0.4f}}, {{0.25f, 0.25f, 0.0f, 1}, {0.05f, 0.4f}},
  };
  const int nr = 1200, nphi = 256;
  for (const auto& lobe : lobes) {
    const double s = std::sqrt(std::max(lobe.a.x, lobe.a.y)) + std::max(lobe.box.x, lobe.box.y);
    std::vector<glm::vec4> h, p;
    std::vector<double> weight;
    for (int i = 0; i < nr; ++i) {
      const double uu = (i + 0.5) / nr, r = s * uu / (1 - uu), dr = s / ((1 - uu) * (1 - uu)) / nr;
      const double cos_t = 1 / std::sqrt(1 + r * r), sin_t = r * cos_t;
      for (int j = 0; j < nphi; ++j) {
        const double phi = 2 * M_PI * (j + 0.5) / nphi;
        h.emplace_back(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t, 0);
        p.push_back(lobe.a);
        weight.push_back(std::pow(cos_t, 4) * r * dr * 2 * M_PI / nphi);
      }
    }
    const std::string body = "vec4 evaluate(vec4 h, vec4 a) {\n"
                             "  Lobe l = Lobe(int(a.w), mat2(a.x, a.z, a.z, a.y), vec2(" +
                             std::to_string(lobe.box.x) + ", " + std::to_string(lobe.box.y) +
                             "));\n  return vec4(lobeNdf(l, h.xyz)); }";
    const auto d = evaluate_glsl(kIncludes, body, h, p);
    double sum = 0;
    for (std::size_t k = 0; k < d.size(); ++k) sum += d[k].x * weight[k];
    EXPECT_NEAR(sum, 1.0, 0.01) << "A = (" << lobe.a.x << ", " << lobe.a.y << ", " << lobe.a.z << "), ndf " << lobe.a.w
                                << ", box " << lobe.box.x << ", " << lobe.box.y;
  }
}

TEST(NdfFiltering, AMillionRandomEvaluationsAreFinite) {
  // Every filter, then the filtered BRDF and its mass over a light's image, for random inputs: alpha
  // down to 1e-4, derivatives from 0 to 1e6, directions down to grazing and below the horizon.
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int n = 1 << 20;
  std::vector<glm::vec4> a(n), b(n);
  for (int i = 0; i < n; ++i) {
    const float alpha = std::pow(10.0f, -4.0f * u(rng));
    const float scale = u(rng) < 0.1f ? 0.0f : std::pow(10.0f, 12.0f * u(rng) - 6.0f);
    a[static_cast<std::size_t>(i)] = glm::vec4(alpha, std::pow(10.0f, -4.0f * u(rng)), u(rng), u(rng));
    b[static_cast<std::size_t>(i)] = glm::vec4(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) * scale;
  }
  const auto gpu = evaluate_glsl(std::string(kIncludes) + kEveryFilter + R"(
vec3 randomDirection(float z, float phi) {
  float c = z * z * z * 2.0 - 1.0;  // dense near the horizon
  float s = sqrt(max(1.0 - c * c, 0.0));
  return vec3(s * cos(phi * 6.2831853), s * sin(phi * 6.2831853), c);
})",
                                 "vec4 evaluate(vec4 a, vec4 b) {\n"
                                 "  int which = int(fract(a.z * 7.31) * 7.0);\n"
                                 "  int ndf = a.w > 0.5 ? 1 : 0;\n"
                                 "  vec4 f = applyFilter(which, ndf, a.xy, b.xy, b.zw, b.xyz);\n"
                                 "  Lobe l = Lobe(ndf, mat2(f.x, f.z, f.z, f.y), vec2(f.w, f.w * 0.5));\n"
                                 "  vec3 wo = randomDirection(a.z, a.w), wi = randomDirection(fract(a.z * 13.7), fract(a.w * 5.3));\n"
                                 "  LightImage image = LightImage(b.xy * fract(a.x * 91.0), mat2(b.zw, b.wz * vec2(1.0, -1.0)) * fract(a.y * 37.0));\n"
                                 "  float mass = lobeMassOnImage(l, image);\n"
                                 "  vec3 s = lobeSpecularCos(l, wo, wi, vec3(0.04));\n"
                                 "  return vec4(s, f.x + f.y + f.z + f.w + mass); }",
                                 a, b);
  int bad = 0;
  for (const auto& v : gpu)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w)) ++bad;
  EXPECT_EQ(bad, 0) << "of " << n;
}
