// The reference's sampling routines (shaders/core/sampling.glsl, lights.glsl) and the BRDF's
// numerics (brdf.glsl), run on the GL device and checked against independent computations in C++:
// chi-square goodness-of-fit tests as in pbrt-v4 and Mitsuba 3 (histograms of many samples against
// expected counts from the density integrated over each bin, sparse bins pooled, a p-value
// threshold with Sidak's correction for the number of tests), the pdfs used for multiple
// importance sampling against the same densities and their integrals, furnace tests, sweeps for
// unbounded sample weights, and renders of the quad-light scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "core/image.hpp"
#include "core/image_io.hpp"
#include "scene/lights/environment_map.hpp"
#include "scratch_directory.hpp"
#include "chi_square.hpp"
#include "gl_fixture.hpp"
#include "scene/scene_loader.hpp"
#include "shading/registry.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// One sample per invocation: llvmpipe stops a shader's loops after 65535 iterations in all.
// 2^21 samples per histogram: a 1% distortion of a mapping fails (in 64 bins; in the BRDF
// samplers' 8 x 8 coarse bins).
constexpr int kSamples = 1 << 21;
// Chi-square tests in this file; each runs at significance 1 - (1 - 0.01)^(1 / kChiSquareTests)
// (Sidak), so that a correct suite fails with probability 1%.
constexpr int kChiSquareTests = 40;

float unit(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

std::vector<glm::vec4> uniforms(int n, std::uint32_t seed, glm::vec2 zw = glm::vec2(0.0f)) {
  std::mt19937 rng(seed);
  std::vector<glm::vec4> u(static_cast<std::size_t>(n));
  for (auto& v : u) v = glm::vec4(unit(rng), unit(rng), zw);
  return u;
}

/// evaluate_glsl in dispatches small enough for one compute grid.
std::vector<glm::vec4> run(const std::string& includes, const std::string& body, const std::vector<glm::vec4>& a,
                           const std::vector<glm::vec4>& b) {
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::vector<glm::vec4> out;
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); i += kChunk) {
    const std::size_t e = std::min(a.size(), i + kChunk);
    const auto part = evaluate_glsl(includes, body, {a.begin() + i, a.begin() + e}, {b.begin() + i, b.begin() + e});
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

// --- Statistics -------------------------------------------------------------------------------

// --- Directions binned around an axis ---------------------------------------------------------

glm::dvec3 dir3(glm::vec4 v) { return glm::normalize(glm::dvec3(v)); }

/// Bins over the sphere in (v, phi) around an axis, v = 1 - cos(angle to the axis) (so that
/// d(omega) = dv dphi), with given v edges from 0; one last bin holds everything beyond them.
struct DirectionBins {
  glm::dvec3 axis, t, b;
  std::vector<double> v_edges;
  int phi_bins = 32;

  DirectionBins(glm::dvec3 a, std::vector<double> edges, int phis) : axis(glm::normalize(a)), v_edges(std::move(edges)), phi_bins(phis) {
    t = glm::normalize(glm::cross(std::abs(axis.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), axis));
    b = glm::cross(axis, t);
  }
  [[nodiscard]] int rings() const { return static_cast<int>(v_edges.size()) - 1; }
  [[nodiscard]] int size() const { return rings() * phi_bins + 1; }
  [[nodiscard]] int index(glm::dvec3 d) const {
    const glm::dvec3 e = d - axis;
    const double v = 0.5 * glm::dot(e, e);  // 1 - cos without cancellation
    const auto ring = std::upper_bound(v_edges.begin(), v_edges.end(), v) - v_edges.begin() - 1;
    if (ring < 0 || ring >= rings()) return size() - 1;
    double phi = std::atan2(glm::dot(d, b), glm::dot(d, t));
    if (phi < 0) phi += 2 * kPi;
    const int p = std::min(phi_bins - 1, static_cast<int>(phi / (2 * kPi) * phi_bins));
    return static_cast<int>(ring) * phi_bins + p;
  }
  [[nodiscard]] glm::dvec3 direction(double v, double phi) const {
    const double s = std::sqrt(std::max(0.0, v * (2 - v)));
    return (1 - v) * axis + s * (std::cos(phi) * t + std::sin(phi) * b);
  }
  /// Quadrature nodes (direction, weight in solid angle, bin): 5 x 5 Gauss-Legendre per bin, on
  /// 8 x 8 sub-cells of bins that `kinked` says an integrand's kink crosses.
  struct Node {
    glm::dvec3 d;
    double w;
    int bin;
  };
  [[nodiscard]] std::vector<Node> nodes(const std::function<bool(glm::dvec3)>& side = {}) const {
    static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                0.2369268850561891};
    std::vector<Node> out;
    const double dphi = 2 * kPi / phi_bins;
    for (int r = 0; r < rings(); ++r)
      for (int p = 0; p < phi_bins; ++p) {
        const double v0 = v_edges[r], v1 = v_edges[r + 1];
        int split = 1;  // 8 where `side` changes over a 5 x 5 grid of the bin, edges included
        if (side) {
          const bool first = side(direction(v0, dphi * p));
          for (int i = 0; i <= 4 && split == 1; ++i)
            for (int j = 0; j <= 4; ++j)
              if (side(direction(v0 + (v1 - v0) * i / 4, dphi * (p + j / 4.0))) != first) split = 8;
        }
        const double dv = (v1 - v0) / split, dp = dphi / split;
        for (int si = 0; si < split; ++si)
          for (int sj = 0; sj < split; ++sj)
            for (int i = 0; i < 5; ++i)
              for (int j = 0; j < 5; ++j) {
                const double v = v0 + dv * (si + 0.5 * (1 + x[i])), phi = dphi * p + dp * (sj + 0.5 * (1 + x[j]));
                out.push_back({direction(v, phi), 0.25 * dv * dp * w[i] * w[j], r * phi_bins + p});
              }
      }
    return out;
  }
};

/// v edges for a lobe of v-scale s: fine near the axis and in geometric progression beyond it,
/// v_k = s ((1 + vmax / s)^(k / K) - 1), so that heavy (GGX) tails keep a bounded ratio per ring.
std::vector<double> lobe_edges(double s, double vmax, int rings) {
  std::vector<double> e;
  for (int k = 0; k <= rings; ++k) e.push_back(k == rings ? vmax : s * (std::pow(1 + vmax / s, double(k) / rings) - 1));
  return e;
}

std::vector<double> uniform_edges(double vmax, int rings) {
  std::vector<double> e;
  for (int k = 0; k <= rings; ++k) e.push_back(vmax * k / rings);
  return e;
}

// --- Independent microfacet formulas (double precision) ---------------------------------------

double ndf_ggx(glm::dvec3 h, glm::dvec2 a) {
  if (h.z <= 0) return 0;
  const double e = h.x * h.x / (a.x * a.x) + h.y * h.y / (a.y * a.y) + h.z * h.z;
  return 1 / (kPi * a.x * a.y * e * e);
}
double ndf_beckmann(glm::dvec3 h, glm::dvec2 a) {
  if (h.z <= 0) return 0;
  const double c2 = h.z * h.z;
  return std::exp(-(h.x * h.x / (a.x * a.x) + h.y * h.y / (a.y * a.y)) / c2) / (kPi * a.x * a.y * c2 * c2);
}
/// Smith Lambda, exact (Heitz 2014, eqs. 72 and 80; Beckmann's with erf, not Walter's fit).
double lambda(bool beckmann, glm::dvec3 w, glm::dvec2 a) {
  const double s = std::sqrt(a.x * a.x * w.x * w.x + a.y * a.y * w.y * w.y);
  if (s == 0) return 0;
  const double m = w.z / s;  // 1 / (alpha tan theta)
  if (beckmann) return 0.5 * (std::exp(-m * m) / (m * std::sqrt(kPi)) - std::erfc(m));
  return 0.5 * (-1 + std::sqrt(1 + 1 / (m * m)));
}
/// D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (Heitz 2018, eq. 3).
double visible_normal_density(glm::dvec3 wo, glm::dvec3 h, glm::dvec2 a) {
  return std::max(0.0, glm::dot(wo, h)) * ndf_ggx(h, a) / (wo.z * (1 + lambda(false, wo, a)));
}
glm::dvec3 reflect_about(glm::dvec3 wo, glm::dvec3 h) { return 2 * glm::dot(wo, h) * h - wo; }
glm::dvec3 spherical(double theta_deg, double phi_deg) {
  const double t = theta_deg * kPi / 180, p = phi_deg * kPi / 180;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

const char* kBrdfIncludes = "#include \"core/sampling.glsl\"\n";

}  // namespace

// --- BRDF sampling --------------------------------------------------------------------------

struct LobeCase {
  double theta, phi;  // wo, degrees
  glm::dvec2 alpha;
};

// Samples h, histograms them around the normal and tests them against the C++ density; the
// GLSL pdf that the reference's MIS uses (as a density of wi) is checked against the same density
// at every quadrature node, integrated to 1, and its own expected counts are chi-square tested too.
void check_normal_sampler(bool beckmann, const std::vector<LobeCase>& cases) {
  for (const auto& c : cases) {
    SCOPED_TRACE((beckmann ? "Beckmann" : "GGX") + std::string(" wo ") + std::to_string(c.theta) + "," +
                 std::to_string(c.phi) + " alpha " + std::to_string(c.alpha.x) + "," + std::to_string(c.alpha.y));
    const glm::dvec3 wo = spherical(c.theta, c.phi);
    const glm::vec4 params(glm::vec3(wo), 0.0f);
    auto a = uniforms(kSamples, 17, glm::vec2(c.alpha));
    const std::vector<glm::vec4> b(a.size(), params);
    const auto h = run(kBrdfIncludes, beckmann ? R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(sampleBeckmannNormal(a.zw, a.xy), 0.0); })"
                                               : R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(sampleGGXVisibleNormal(b.xyz, a.zw, a.xy), 0.0); })",
                       a, b);
    const DirectionBins bins({0, 0, 1}, lobe_edges(0.5 * c.alpha.x * c.alpha.y, 1.0, 24), 32);
    std::vector<double> observed(static_cast<std::size_t>(bins.size()), 0.0);
    double facing = 0;  // samples with wo.h > 0
    for (const auto& v : h) {
      ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
      const glm::dvec3 d = dir3(v);
      observed[static_cast<std::size_t>(bins.index(d))] += 1;
      if (glm::dot(wo, d) > 0) facing += 1;
    }
    auto density = [&](glm::dvec3 m) {
      return beckmann ? ndf_beckmann(m, c.alpha) * m.z : visible_normal_density(wo, m, c.alpha);
    };
    // The GLSL pdf at each node's reflected direction, turned into a density of h: p(wi) 4 |wo.h|.
    // The visible-normal density has a kink at wo.h = 0.
    const auto nodes = bins.nodes([&](glm::dvec3 m) { return glm::dot(wo, m) > 0; });
    std::vector<glm::vec4> na, nb;
    for (const auto& n : nodes) {
      na.emplace_back(glm::vec3(reflect_about(wo, n.d)), static_cast<float>(c.alpha.x));
      nb.emplace_back(glm::vec3(wo), static_cast<float>(c.alpha.y));
    }
    const auto pdf = run(kBrdfIncludes, beckmann ? R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(beckmannReflectionPdf(b.xyz, a.xyz, vec2(a.w, b.w))); })"
                                                 : R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(ggxVisibleReflectionPdf(b.xyz, a.xyz, vec2(a.w, b.w))); })",
                         na, nb);
    std::vector<double> expected(observed.size(), 0.0), expected_glsl(observed.size(), 0.0);
    double peak = 0;
    for (const auto& n : nodes) peak = std::max(peak, density(n.d));
    double glsl_total = 0, glsl_facing = 0, worst = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto& n = nodes[i];
      const double exact = density(n.d);
      const double oh = glm::dot(wo, n.d);
      const double glsl = pdf[i].x * 4 * std::abs(oh);
      expected[static_cast<std::size_t>(n.bin)] += kSamples * n.w * exact;
      expected_glsl[static_cast<std::size_t>(n.bin)] += kSamples * n.w * glsl;
      glsl_total += n.w * glsl;
      // Beckmann's pdf is that of directions above the microsurface (wo.h > 0) only.
      if (oh > 0) glsl_facing += n.w * glsl;
      // (Where wo.h -> 0, wo + wi cancels in float and h loses its precision.)
      if (oh > 0.02 && exact > 1e-3 * peak) worst = std::max(worst, std::abs(glsl - exact) / exact);
    }
    EXPECT_LT(worst, 2e-3) << "GLSL pdf against the density";
    double inside = 0;
    for (std::size_t i = 0; i + 1 < expected.size(); ++i) inside += expected[i];
    expected.back() = std::max(0.0, kSamples - inside);  // below the horizon: nothing
    const ChiSquare chi = chi_square(observed, expected);
    EXPECT_TRUE(chi.passes(kChiSquareTests)) << chi;
    // The same counts in 8 x 8 coarse bins: more power against smooth distortions (1% in azimuth).
    std::vector<double> coarse_obs(65, 0.0), coarse_exp(65, 0.0);
    for (int i = 0; i + 1 < bins.size(); ++i) {
      const int coarse = (i / bins.phi_bins) / 3 * 8 + (i % bins.phi_bins) / 4;
      coarse_obs[static_cast<std::size_t>(coarse)] += observed[static_cast<std::size_t>(i)];
      coarse_exp[static_cast<std::size_t>(coarse)] += expected[static_cast<std::size_t>(i)];
    }
    coarse_obs.back() = observed.back();
    coarse_exp.back() = expected.back();
    const ChiSquare chi_coarse = chi_square(coarse_obs, coarse_exp);
    EXPECT_TRUE(chi_coarse.passes(kChiSquareTests)) << "8 x 8 bins: " << chi_coarse;
    if (beckmann) {
      // Integrates to the fraction of samples it describes (wo.h > 0), within 4 sigma.
      const double f = facing / kSamples;
      EXPECT_NEAR(glsl_facing, f, 4 * std::sqrt(f * (1 - f) / kSamples) + 2e-4);
    } else {
      EXPECT_NEAR(glsl_total, 1.0, 1e-3) << "visible normals integrate to 1 (Heitz 2018, eq. 2)";
      expected_glsl.back() = std::max(0.0, kSamples * (1 - glsl_total));
      const ChiSquare chi_glsl = chi_square(observed, expected_glsl);
      EXPECT_TRUE(chi_glsl.passes(kChiSquareTests)) << "expected counts from the GLSL pdf: " << chi_glsl;
    }
    std::printf("%s wo %.0f alpha %.2f,%.2f: chi2 %.1f dof %d p %.3f (8 x 8: p %.3f)\n", beckmann ? "beckmann" : "ggx",
                c.theta, c.alpha.x, c.alpha.y, chi.chi2, chi.dof, chi.p, chi_coarse.p);
  }
}

TEST(SamplingChiSquare, GgxVisibleNormals) {
  check_normal_sampler(false, {{0, 0, {0.05, 0.05}},
                               {45, 30, {0.2, 0.2}},
                               {75, 10, {0.5, 0.5}},
                               {89, 0, {0.3, 0.3}},
                               {60, 40, {0.1, 0.4}},
                               {30, 120, {1.0, 1.0}}});
}

TEST(SamplingChiSquare, BeckmannNormals) {
  check_normal_sampler(true, {{0, 0, {0.05, 0.05}}, {40, 20, {0.3, 0.3}}, {70, 0, {0.8, 0.8}}, {50, 60, {0.1, 0.5}}});
}

// --- Light sampling ---------------------------------------------------------------------------

namespace {

/// A scene with one light, given as the keys of its [[light]] table (and an object far away,
/// which nothing here looks at).
TestScene light_scene(const std::string& light) {
  return TestScene().material("m").sphere("m", {{"radius", 0.01}, {"translate", {0, -100, 0}}}).raw("[[light]]\n" + light);
}

const char* kLightIncludes = "#include \"lights/lights.glsl\"\n";

/// Samples of sampleLightDirection from p: xyz = dir * dist (so that q = p + xyz), w = pdf, or
/// w = -1 where the sample was rejected.
std::vector<glm::vec4> light_samples(SceneFixture& f, glm::dvec3 p, std::uint32_t seed) {
  f.gpu->bind_buffers();
  const auto a = uniforms(kSamples, seed);
  const std::vector<glm::vec4> b(a.size(), glm::vec4(glm::vec3(p), 0.0f));
  return run(kLightIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec3 dir; float dist, pdf;
  bool ok = sampleLightDirection(lights[0], b.xyz, a.xy, dir, dist, pdf);
  return ok ? vec4(dir * min(dist, 1e20), pdf) : vec4(0.0, 0.0, 0.0, -1.0);
})",
             a, b);
}

struct ConeCase {
  std::string light;  // TOML of the light
  glm::dvec3 p;       // shading point
  glm::dvec3 axis;    // towards the cone's centre
  double one_minus_cos;
};

/// Uniform sampling of a cone (suns, and spheres seen from outside), in 1 - cos and azimuth.
void check_cone(const ConeCase& c, std::uint32_t seed) {
  SceneFixture f(light_scene(c.light));
  const auto s = light_samples(f, c.p, seed);
  // Uniform in (1 - cos, phi); the last ring takes directions within float rounding of the edge.
  auto edges = uniform_edges(c.one_minus_cos, 8);
  edges.back() *= 1 + 2e-3;
  const DirectionBins bins(c.axis, edges, 8);
  std::vector<double> observed(static_cast<std::size_t>(bins.size()), 0.0);
  std::vector<double> expected(observed.size(), static_cast<double>(kSamples) / (bins.size() - 1));
  expected.back() = 0;
  const double pdf = 1 / (2 * kPi * c.one_minus_cos);
  double rejected = 0, worst_pdf = 0;
  for (const auto& v : s) {
    if (v.w < 0) {
      rejected += 1;
      continue;
    }
    observed[static_cast<std::size_t>(bins.index(dir3(v)))] += 1;
    worst_pdf = std::max(worst_pdf, std::abs(v.w / pdf - 1));
  }
  EXPECT_LT(rejected, 1e-4 * kSamples) << "samples of the cone that miss the light";
  EXPECT_EQ(observed.back(), 0.0) << "samples outside the cone";
  EXPECT_LT(worst_pdf, 1e-4) << "lightPdf against 1 / (2 pi (1 - cos))";
  observed.pop_back();
  expected.pop_back();
  const ChiSquare chi = chi_square(observed, expected);
  EXPECT_TRUE(chi.passes(kChiSquareTests)) << chi;
  std::printf("cone 1-cos %.3g: chi2 %.1f dof %d p %.3f, rejected %.0f, pdf error %.2g\n", c.one_minus_cos, chi.chi2,
              chi.dof, chi.p, rejected, worst_pdf);
}

}  // namespace

TEST(SamplingChiSquare, SunCones) {
  const glm::dvec3 travel = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
  std::uint32_t seed = 100;
  for (double degrees : {0.25, 0.5, 2.0, 20.0}) {
    SCOPED_TRACE("sun of " + std::to_string(degrees) + " degrees");
    const double half = 0.5 * degrees * kPi / 180;
    check_cone({"type = \"directional\"\ndirection = [0.3, -1.0, 0.2]\nangular_radius = " + std::to_string(degrees) + "\n",
                {0, 0, 0}, -travel, 2 * std::sin(half) * std::sin(half)},
               seed++);
  }
}

TEST(SamplingChiSquare, SphereLightCones) {
  struct Sphere {
    glm::dvec3 c;
    double r;
  };
  std::uint32_t seed = 200;
  // Close (half-angle 59 degrees), moderate, and far (1 - cos = 5e-7, under 9 float steps at 1).
  for (const Sphere s : {Sphere{{0.3, 1.1, 0.2}, 1.0}, Sphere{{0, 0, 3}, 1.0}, Sphere{{1, 2, 1000}, 1.0}}) {
    SCOPED_TRACE("sphere at distance " + std::to_string(glm::length(s.c)));
    const double sin2 = s.r * s.r / glm::dot(s.c, s.c);
    char light[256];
    std::snprintf(light, sizeof light, "type = \"sphere\"\nposition = [%.17g, %.17g, %.17g]\nradius = %.17g\n", s.c.x,
                  s.c.y, s.c.z, s.r);
    check_cone({light, {0, 0, 0}, s.c, sin2 / (1 + std::sqrt(1 - sin2))}, seed++);
  }
}

// The environment light's sampler (shaders/lights/environment.glsl): texels in proportion to
// luminance x sin(theta), uniform in (u, v) within each (2 x 2 sub-bins per texel), on a map with
// a gradient and a hot spot, turned by 30 degrees; its pdf against the same density at each sample.
TEST(SamplingChiSquare, EnvironmentByLuminanceAndSinTheta) {
  ScratchDirectory scratch;
  constexpr int kW = 32, kH = 16;
  Image map(kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) map.at(x, y) = glm::vec3(0.2f + 0.05f * x, 0.1f + 0.1f * y, 0.3f);
  map.at(20, 5) = glm::vec3(60.0f, 50.0f, 40.0f);  // the hot spot
  map.at(3, 12) = glm::vec3(0.0f);                 // a black texel: never sampled
  const auto file = scratch.path() / "map.exr";
  write_exr(file, {{"", &map}});
  SceneFixture f(light_scene("type = \"environment\"\nfile = \"" + file.string() + "\"\nrotation = 30\n"));
  f.gpu->resources().bind(f.gpu->scene_resource_ids(), f.gpu->resource_context());
  const auto s = light_samples(f, {0, 0, 0}, 300);
  // Texel probabilities from the map itself: f = luminance sin(theta at the row's centre).
  std::vector<double> weight(kW * kH);
  double total = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      total += weight[y * kW + x] = luminance(map.at(x, y)) * std::sin(kPi * (y + 0.5) / kH);
  const double turn = 30 * kPi / 180;
  std::vector<double> observed(4 * kW * kH, 0.0), expected(observed.size(), 0.0);
  double pdf_mismatches = 0, rejected = 0;
  for (const auto& v : s) {
    if (v.w < 0) {
      rejected += 1;
      continue;
    }
    const glm::dvec3 d = dir3(v);
    const glm::dvec3 m(std::cos(turn) * d.x - std::sin(turn) * d.z, d.y, std::sin(turn) * d.x + std::cos(turn) * d.z);
    const glm::dvec2 uv = environment_uv(m);
    const int x = std::min(kW - 1, int(uv.x * kW)), y = std::min(kH - 1, int(uv.y * kH));
    const int sx = std::min(1, int((uv.x * kW - x) * 2)), sy = std::min(1, int((uv.y * kH - y) * 2));
    observed[4 * (y * kW + x) + 2 * sy + sx] += 1;
    const double pdf = weight[y * kW + x] / total * kW * kH / (2 * kPi * kPi * std::sin(kPi * uv.y));
    pdf_mismatches += std::abs(v.w / pdf - 1) > 1e-3;  // a texel's edge rounded to its neighbour
  }
  for (std::size_t i = 0; i < expected.size(); ++i) expected[i] = kSamples * weight[i / 4] / total / 4;
  // Directions float rounds into a neighbouring texel (a black one: rejected) are rare, and
  // only there may lightPdf differ from the density by more than the float CDFs' precision.
  EXPECT_LT(rejected, 1e-4 * kSamples);
  EXPECT_EQ(observed[4 * (12 * kW + 3)], 0.0) << "the black texel";
  EXPECT_LT(pdf_mismatches, 2e-3 * kSamples) << "lightPdf against luminance sin(theta) / (I 2 pi^2 sin(theta))";
  const ChiSquare chi = chi_square(observed, expected);
  EXPECT_TRUE(chi.passes(kChiSquareTests)) << chi;
}

namespace {

struct AreaCase {
  bool disk;
  glm::dvec3 centre, normal, up;
  glm::dvec2 size;  // disk: radius in x
  glm::dvec3 p;
};

/// Area lights are sampled uniformly by area: histogram over the light's own coordinates (disk:
/// r^2 / R^2 and angle, quad: the two edge coordinates), and the GLSL pdf checked pointwise
/// against dist^2 / (A cos) and integrated over the light's solid angle.
void check_area_light(const AreaCase& c, std::uint32_t seed) {
  char light[512];
  if (c.disk)
    std::snprintf(light, sizeof light,
                  "type = \"disk\"\nposition = [%.17g, %.17g, %.17g]\ndirection = [%.17g, %.17g, %.17g]\nradius = %.17g\n",
                  c.centre.x, c.centre.y, c.centre.z, c.normal.x, c.normal.y, c.normal.z, c.size.x);
  else
    std::snprintf(light, sizeof light,
                  "type = \"quad\"\nposition = [%.17g, %.17g, %.17g]\ndirection = [%.17g, %.17g, %.17g]\n"
                  "up = [%.17g, %.17g, %.17g]\nsize = [%.17g, %.17g]\n",
                  c.centre.x, c.centre.y, c.centre.z, c.normal.x, c.normal.y, c.normal.z, c.up.x, c.up.y, c.up.z,
                  c.size.x, c.size.y);
  SceneFixture f(light_scene(light));
  const auto s = light_samples(f, c.p, seed);
  const glm::dvec3 n = glm::normalize(c.normal);
  // The quad's edges as the scene format defines them: u = up x normal, v = normal x u.
  const glm::dvec3 u = glm::normalize(glm::cross(c.up, n)), v = glm::cross(n, u);
  const double area = c.disk ? kPi * c.size.x * c.size.x : c.size.x * c.size.y;
  // Bins: disk (r^2, angle), quad (u, v); few, so that smooth distortions of 1-2% show.
  constexpr int kA = 8, kB = 8;
  auto coords = [&](glm::dvec3 q) {  // in [0, 1)^2 on the light
    const glm::dvec3 d = q - c.centre;
    const double x = glm::dot(d, u), y = glm::dot(d, v);
    if (!c.disk) return glm::dvec2(x / c.size.x + 0.5, y / c.size.y + 0.5);
    double phi = std::atan2(y, x);
    if (phi < 0) phi += 2 * kPi;
    return glm::dvec2((x * x + y * y) / (c.size.x * c.size.x), phi / (2 * kPi));
  };
  auto point = [&](glm::dvec2 t) {
    if (!c.disk) return c.centre + (t.x - 0.5) * c.size.x * u + (t.y - 0.5) * c.size.y * v;
    const double r = c.size.x * std::sqrt(t.x), phi = 2 * kPi * t.y;
    return c.centre + r * (std::cos(phi) * u + std::sin(phi) * v);
  };
  std::vector<double> observed(kA * kB, 0.0);
  double outside = 0, rejected = 0, worst_pdf = 0;
  for (const auto& w : s) {
    if (w.w < 0) {
      rejected += 1;
      continue;
    }
    const glm::dvec3 q = c.p + glm::dvec3(w);
    const glm::dvec2 t = coords(q);
    const double off_plane = std::abs(glm::dot(q - c.centre, n));
    if (t.x < -1e-5 || t.x > 1 + 1e-5 || t.y < -1e-5 || t.y > 1 + 1e-5 || off_plane > 1e-5 * glm::length(glm::dvec3(w))) {
      outside += 1;
      continue;
    }
    const int i = std::clamp(static_cast<int>(t.x * kA), 0, kA - 1), j = std::clamp(static_cast<int>(t.y * kB), 0, kB - 1);
    observed[static_cast<std::size_t>(i * kB + j)] += 1;
    const glm::dvec3 d = glm::dvec3(w);
    const double dist = glm::length(d), cos_l = std::abs(glm::dot(d, n)) / dist;
    worst_pdf = std::max(worst_pdf, std::abs(w.w / (dist * dist / (area * cos_l)) - 1));
  }
  EXPECT_EQ(rejected, 0.0) << "the point sees the light's front: no sample may be rejected";
  EXPECT_EQ(outside, 0.0) << "samples off the light";
  EXPECT_LT(worst_pdf, 1e-3) << "lightPdf against dist^2 / (A cos)";
  const ChiSquare chi = chi_square(observed, std::vector<double>(observed.size(), double(kSamples) / (kA * kB)));
  EXPECT_TRUE(chi.passes(kChiSquareTests)) << chi;

  // The GLSL pdf over the light's solid angle: int pdf cos / dist^2 dA = 1 (Gauss-Legendre).
  static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double wt[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  std::vector<glm::vec4> na, nb;
  std::vector<double> jac;
  for (int i = 0; i < kA; ++i)
    for (int j = 0; j < kB; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) {
          const glm::dvec2 t((i + 0.5 * (1 + x[k])) / kA, (j + 0.5 * (1 + x[l])) / kB);
          const glm::dvec3 d = point(t) - c.p;
          const double dist = glm::length(d);
          na.emplace_back(glm::vec3(d / dist), static_cast<float>(dist));
          nb.emplace_back(glm::vec3(c.p), 0.0f);
          // dA = area dt1 dt2 for both parametrisations; solid angle = cos / dist^2 dA.
          jac.push_back(area * 0.25 * wt[k] * wt[l] / (kA * kB) * std::abs(glm::dot(d, n)) / (dist * dist * dist));
        }
  f.gpu->bind_buffers();
  const auto pdf = run(kLightIncludes, "vec4 evaluate(vec4 a, vec4 b) { return vec4(lightPdf(lights[0], b.xyz, a.xyz, a.w)); }",
                       na, nb);
  double integral = 0;
  for (std::size_t i = 0; i < pdf.size(); ++i) integral += pdf[i].x * jac[i];
  EXPECT_NEAR(integral, 1.0, 1e-4) << "lightPdf over the light's solid angle";
  std::printf("%s: chi2 %.1f dof %d p %.3f, pdf error %.2g, integral %.7f\n", c.disk ? "disk" : "quad", chi.chi2, chi.dof,
              chi.p, worst_pdf, integral);
}

}  // namespace

TEST(SamplingChiSquare, DiskLights) {
  // On the axis and close, oblique, and far at a grazing 80 degrees.
  check_area_light({true, {0, 0, 0.5}, {0, 0, -1}, {0, 1, 0}, {1.0, 0}, {0, 0, 0}}, 300);
  check_area_light({true, {1.5, 0.5, 2.5}, {-0.2, 0.1, -1}, {0, 1, 0}, {0.7, 0}, {0, 0, 0}}, 301);
  check_area_light({true, {4.9, 0, 0.87}, {0, 0, -1}, {0, 1, 0}, {0.5, 0}, {0, 0, 0}}, 302);
}

TEST(SamplingChiSquare, QuadLights) {
  check_area_light({false, {0, 0, 0.5}, {0, 0, -1}, {0, 1, 0}, {2.0, 1.0}, {0, 0, 0}}, 400);
  check_area_light({false, {1.5, 0.5, 2.5}, {-0.2, 0.1, -1}, {0.3, 1, 0}, {0.4, 1.6}, {0, 0, 0}}, 401);
  check_area_light({false, {4.9, 0, 0.87}, {0, 0, -1}, {1, 1, 0}, {1.0, 0.3}, {0, 0, 0}}, 402);
}

// --- Light numerics at small angles -----------------------------------------------------------

TEST(LightNumerics, SunIrradianceIsExactAtSmallAngles) {
  // The exact 1 - cos reaches the shader (in float from cos it is off by 1.7% at 0.1 degrees), and
  // E = int L cos over the cone: with the sun's radiance E / (pi sin^2) and uniform cone samples,
  // L cos / pdf averages to exactly E (radiance and pdf must use the same cone).
  for (double degrees : {0.1, 0.25, 0.5, 2.0}) {
    SCOPED_TRACE(std::to_string(degrees) + " degrees");
    SceneFixture f(light_scene("type = \"directional\"\ndirection = [0.3, -1.0, 0.2]\nirradiance = 1\nangular_radius = " +
                               std::to_string(degrees) + "\n"));
    f.gpu->bind_buffers();
    const auto a = uniforms(1 << 16, 5);
    const auto r = run(kLightIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 dir; float dist, pdf;
  sampleLightDirection(L, vec3(0.0), a.xy, dir, dist, pdf);
  return vec4(lightRadiance(L).r * dot(dir, -L.direction_cos.xyz) / pdf, sunOneMinusCos(L), 0.0, 0.0);
})",
                       a, a);
    double sum = 0;
    for (const auto& v : r) sum += v.x;
    const double half = 0.5 * degrees * kPi / 180;
    EXPECT_NEAR(r[0].y / (2 * std::sin(half) * std::sin(half)), 1.0, 1e-6) << "sunOneMinusCos";
    EXPECT_NEAR(sum / static_cast<double>(r.size()), 1.0, 2e-5) << "irradiance from the cone";
  }
}

TEST(LightNumerics, ConeEdgesAreClassifiedExactly) {
  // Directions 0.2% to 1% of the half-angle inside or outside the edge of a 0.25-degree sun and of
  // a sphere 1000 radii away: lightHit must tell them apart (a float cosine cannot at 0.25
  // degrees, and b^2 - |oc|^2 + r^2 loses the sphere's silhouette to cancellation).
  struct Case {
    std::string light;
    glm::dvec3 axis;
    double half_angle;
  };
  const glm::dvec3 c(1, 2, 1000);
  const std::vector<Case> cases = {
      {"type = \"directional\"\ndirection = [0.3, -1.0, 0.2]\nangular_radius = 0.25\n",
       -glm::normalize(glm::dvec3(0.3, -1.0, 0.2)), 0.25 * kPi / 180},
      {"type = \"sphere\"\nposition = [1, 2, 1000]\nradius = 1\n", glm::normalize(c), std::asin(1 / glm::length(c))}};
  for (const auto& k : cases) {
    SceneFixture f(light_scene(k.light));
    f.gpu->bind_buffers();
    const DirectionBins frame(k.axis, {0, 1}, 1);
    std::mt19937 rng(9);
    std::vector<glm::vec4> dirs;
    std::vector<int> inside;
    for (int i = 0; i < 100000; ++i) {
      const double delta = (0.002 + 0.008 * unit(rng)) * (i % 2 ? 1 : -1);
      const double angle = k.half_angle * (1 + delta), phi = 2 * kPi * unit(rng);
      dirs.emplace_back(glm::vec3(frame.direction(1 - std::cos(angle), phi)), 0.0f);
      inside.push_back(delta < 0);
    }
    const auto hit = run(kLightIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) { float d; return vec4(lightHit(lights[0], vec3(0.0), a.xyz, d) ? 1.0 : 0.0); })",
                         dirs, dirs);
    int wrong = 0;
    for (std::size_t i = 0; i < hit.size(); ++i) wrong += (hit[i].x > 0.5f) != (inside[i] != 0);
    EXPECT_EQ(wrong, 0) << k.light;
  }
}

// --- The BRDF: normalisation, furnace, grazing sweeps -----------------------------------------

TEST(BrdfNumerics, NdfProjectedAreaIsOneAndVisibleNormalsAreNormalised) {
  // int D(h) h.z dh = 1, and int max(0, wo.h) D(h) dh = wo.z / G1(wo) (Heitz 2014, eq. 2 with
  // eq. 18), down to wo.z = 1e-7, where a floored Lambda loses G1 entirely.
  struct Case {
    int kind;
    glm::dvec2 alpha;
  };
  const std::vector<Case> cases = {{0, {0.01, 0.01}}, {0, {0.05, 0.05}}, {0, {0.3, 0.3}}, {0, {1.0, 1.0}},
                                   {0, {0.05, 0.5}},  {0, {0.8, 0.1}},   {1, {0.01, 0.01}}, {1, {0.3, 0.3}},
                                   {1, {1.0, 1.0}},   {1, {0.05, 0.5}},  {1, {0.8, 0.1}}};
  const std::vector<glm::dvec3> views = {spherical(0, 0), spherical(60, 30), spherical(89, 70),
                                         glm::normalize(glm::dvec3(0.6, -0.8, 1e-3)), glm::normalize(glm::dvec3(-0.6, 0.8, 1e-7))};
  for (const auto& c : cases) {
    const DirectionBins bins({0, 0, 1}, lobe_edges(0.5 * c.alpha.x * c.alpha.y, 1.0, 32), 48);
    const auto nodes = bins.nodes();
    std::vector<glm::vec4> a, b;
    for (const auto& n : nodes) a.emplace_back(glm::vec3(n.d), static_cast<float>(c.kind));
    // The views ride along in b (one per invocation; G1 is evaluated for each of them).
    for (std::size_t i = 0; i < nodes.size(); ++i) b.emplace_back(glm::vec3(views[i % views.size()]), 0.0f);
    const auto d = run(kBrdfIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec2 alpha = vec2()" + std::to_string(c.alpha.x) + ", " + std::to_string(c.alpha.y) + R"();
  return vec4(ndf(int(a.w), a.xyz, alpha), smithG1(int(a.w), b.xyz, alpha), 0.0, 0.0);
})",
                       a, b);
    double projected = 0;
    std::vector<double> visible(views.size(), 0.0);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      projected += nodes[i].w * d[i].x * nodes[i].d.z;
      for (std::size_t k = 0; k < views.size(); ++k)
        visible[k] += nodes[i].w * d[i].x * std::max(0.0, glm::dot(views[k], nodes[i].d));
    }
    const std::string label = (c.kind ? "Beckmann alpha " : "GGX alpha ") + std::to_string(c.alpha.x) + "," +
                              std::to_string(c.alpha.y);
    EXPECT_NEAR(projected, 1.0, 1e-3) << label;
    for (std::size_t k = 0; k < views.size(); ++k) {
      // (At grazing views the kink of max(0, wo.h) crosses a narrow peak, beyond this quadrature;
      // the sweep below checks G1 there against the exact Lambda.)
      if (views[k].z < 0.01 && c.alpha.x < 0.05) continue;
      const double g1 = d[k].y;  // node k carried view k
      // Beckmann's G1 is Walter's rational fit of Lambda (0.35% at most on G1).
      EXPECT_NEAR(g1 * visible[k] / views[k].z, 1.0, c.kind ? 5e-3 : 1e-3) << label << " wo.z " << views[k].z;
    }
  }
}

namespace {

/// Per sample of the reference's BRDF strategy: x = specularCos(f0 = 1) / pdf for wi above the
/// horizon (else 0), yzw = the sampled normal h.
std::vector<glm::vec4> furnace_samples(int kind, glm::dvec3 wo, glm::dvec2 alpha, int n, std::uint32_t seed) {
  const auto a = uniforms(n, seed, glm::vec2(alpha));
  const std::vector<glm::vec4> b(a.size(), glm::vec4(glm::vec3(wo), static_cast<float>(kind)));
  return run(kBrdfIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  int kind = int(b.w);
  vec3 wo = b.xyz;
  vec3 h = kind == 1 ? sampleBeckmannNormal(a.zw, a.xy) : sampleGGXVisibleNormal(wo, a.zw, a.xy);
  vec3 wi = reflect(-wo, h);
  float pdf = kind == 1 ? beckmannReflectionPdf(wo, wi, a.zw) : ggxVisibleReflectionPdf(wo, wi, a.zw);
  float f = specularCos(kind, wo, wi, a.zw, vec3(1.0)).r;
  return vec4(wi.z > 0.0 && pdf > 0.0 ? f / pdf : 0.0, h);
})",
             a, b);
}

}  // namespace

TEST(BrdfNumerics, WhiteFurnace) {
  // f0 = 1: the specular albedo int f cos dwi, estimated with the reference's own BRDF samples and
  // pdfs, is at most 1 (height-correlated Smith only loses energy, more with roughness), and each
  // sample's weight f cos / pdf matches G2 / G1(wo) (GGX; D and 4 wo.z cancel) or
  // G2 wo.h / (wo.z h.z) (Beckmann), computed here with the exact Lambda.
  const int n = 1 << 18;
  for (int kind : {0, 1}) {
    for (double theta : {0.0, 45.0, 80.0, 89.9}) {
      double previous = 2;
      for (double a : {0.05, 0.3, 1.0}) {
        const glm::dvec3 wo = spherical(theta, 25);
        const glm::dvec2 alpha(a, kind == 0 && a == 0.3 ? 0.6 : a);
        const auto s = furnace_samples(kind, wo, alpha, n, 7);
        double sum = 0, sum2 = 0, worst = 0;
        const bool beckmann = kind == 1;
        for (const auto& v : s) {
          ASSERT_TRUE(std::isfinite(v.x));
          sum += v.x;
          sum2 += double(v.x) * v.x;
          const glm::dvec3 h = glm::normalize(glm::dvec3(v.y, v.z, v.w)), wi = reflect_about(wo, h);
          if (wi.z <= 1e-2 || glm::dot(wo, h) <= 1e-2) continue;  // (where float h decides Lambda(wi))
          const double lo = lambda(beckmann, wo, alpha), li = lambda(beckmann, wi, alpha);
          const double g2 = 1 / (1 + lo + li);
          const double exact = beckmann ? g2 * glm::dot(wo, h) / (wo.z * h.z) : g2 * (1 + lo);
          worst = std::max(worst, std::abs(v.x - exact) / exact);
        }
        const double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        const std::string label = (beckmann ? "Beckmann" : "GGX") + std::string(" theta ") + std::to_string(theta) +
                                  " alpha " + std::to_string(a);
        EXPECT_LE(mean, 1 + 4 * sigma + 1e-5) << label;
        // Beckmann's Lambda is Walter's fit in the shader.
        EXPECT_LT(worst, beckmann ? 1e-2 : 1e-3) << label << ": sample weight against G2 / G1";
        if (theta <= 45 && a == 0.05) {
          EXPECT_GT(mean, 0.99) << label;
        }
        EXPECT_LT(mean, previous + 4 * sigma) << label << ": albedo must fall with roughness";
        previous = mean;
        std::printf("%s theta %.1f alpha %.2f: albedo %.4f +- %.4f, weight error %.2g\n", beckmann ? "beckmann" : "ggx",
                    theta, a, mean, sigma, worst);
      }
    }
  }
  // Lambert: uniform hemisphere samples, 2 pi diffuseCos averages to the albedo.
  std::mt19937 rng(8);
  std::vector<glm::vec4> wi;
  for (int i = 0; i < n; ++i) {
    const double z = unit(rng), phi = 2 * kPi * unit(rng), r = std::sqrt(1 - z * z);
    wi.emplace_back(r * std::cos(phi), r * std::sin(phi), z, 0.0f);
  }
  const auto d = run(kBrdfIncludes, "vec4 evaluate(vec4 a, vec4 b) { return vec4(diffuseCos(vec3(1.0), a.xyz), 0.0); }", wi, wi);
  double sum = 0;
  for (const auto& v : d) sum += 2 * kPi * v.x;
  EXPECT_NEAR(sum / n, 1.0, 4 * std::sqrt(1.0 / 3 / n));  // 2 z for z uniform: variance 1/3
}

TEST(BrdfNumerics, GrazingSweepHasNoFireflies) {
  // Two million random (wo, wi, alpha), half of the views and a quarter of the lights within
  // 1e-9 .. 1 of the horizon (a shading normal nearly perpendicular to the view), alpha from 1e-3
  // to 1, anisotropic. specularCos must match the BRDF computed here in double with the exact
  // Lambda (it stays bounded as wo.z -> 0: G2 / wo.z -> 1 / (wo.z Lambda(wo))), and a GGX sample's
  // weight specularCos / pdf is G2 / G1 <= F. With the power heuristic every contribution of the
  // reference's MIS estimator is at most radiance x specularCos / pdf_brdf, so this bounds them.
  const int n = 1 << 20;
  std::mt19937 rng(12);
  auto horizon_z = [&](bool grazing) { return grazing ? std::pow(10.0, -9.0 + 9.0 * unit(rng)) : 1e-3 + 0.999 * unit(rng); };
  auto direction = [&](double z) {
    const double phi = 2 * kPi * unit(rng), r = std::sqrt(std::max(0.0, 1 - z * z));
    return glm::vec3(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
  };
  std::vector<glm::vec4> a(n), b(n);
  for (int i = 0; i < n; ++i) {
    const float ax = static_cast<float>(std::pow(10.0, -3.0 + 3.0 * unit(rng)));
    const float ay = static_cast<float>(std::pow(10.0, -3.0 + 3.0 * unit(rng)));
    a[static_cast<std::size_t>(i)] = glm::vec4(direction(horizon_z(i % 2 == 0)), ax);
    b[static_cast<std::size_t>(i)] = glm::vec4(direction(horizon_z(i % 4 == 1)), ay);
  }
  for (int kind : {0, 1}) {
    const auto r = run(kBrdfIncludes, std::string(R"(
vec4 evaluate(vec4 a, vec4 b) {
  int kind = )") + std::to_string(kind) + R"(;
  vec2 alpha = vec2(a.w, b.w);
  float f = specularCos(kind, a.xyz, b.xyz, alpha, vec3(1.0)).r;
  float pdf = kind == 1 ? beckmannReflectionPdf(a.xyz, b.xyz, alpha) : ggxVisibleReflectionPdf(a.xyz, b.xyz, alpha);
  return vec4(f, pdf, 0.0, 0.0);
})",
                       a, b);
    double worst = 0, worst_weight = 0, largest = 0;
    int bad = 0;
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 wo(a[static_cast<std::size_t>(i)]), wi(b[static_cast<std::size_t>(i)]);
      const glm::dvec2 alpha(a[static_cast<std::size_t>(i)].w, b[static_cast<std::size_t>(i)].w);
      const glm::vec4 g = r[static_cast<std::size_t>(i)];
      if (!std::isfinite(g.x) || !std::isfinite(g.y) || g.x < 0 || g.y < 0) {
        ++bad;
        continue;
      }
      const glm::dvec3 h = glm::normalize(wo + wi);
      const bool beckmann = kind == 1;
      const double d = beckmann ? ndf_beckmann(h, alpha) : ndf_ggx(h, alpha);
      const double lo = lambda(beckmann, wo, alpha), li = lambda(beckmann, wi, alpha);
      // G2 / wo.z with wo.z Lambda(wo) kept finite: 1 / (wo.z + wo.z Lo + wo.z Li).
      const double exact = 0.25 * d / (wo.z * (1 + li) + wo.z * lo);
      // Relative error, with an absolute floor at 1e-6 of the lobe's peak (float h near the peak).
      const double scale = 1 / (kPi * alpha.x * alpha.y * std::max(wo.z + wo.z * lo, 1e-30));
      worst = std::max(worst, std::abs(g.x - exact) / (exact + 1e-6 * scale));
      largest = std::max(largest, static_cast<double>(g.x) * alpha.x * alpha.y);
      if (!beckmann && g.y > 0) worst_weight = std::max(worst_weight, static_cast<double>(g.x) / g.y);
    }
    SCOPED_TRACE(kind ? "Beckmann" : "GGX");
    EXPECT_EQ(bad, 0) << "non-finite or negative values";
    // Beckmann's Lambda in the shader is Walter's rational fit.
    EXPECT_LT(worst, kind ? 2e-2 : 2e-3) << "specularCos against double precision";
    if (kind == 0) {
      EXPECT_LE(worst_weight, 1 + 1e-4) << "a GGX sample weight above F = 1";
    }
    std::printf("%s: worst relative error %.3g, largest specularCos alpha_x alpha_y %.3g, largest GGX weight %.6f\n",
                kind ? "beckmann" : "ggx", worst, largest, worst_weight);
  }
}

// --- Quad lights in renders -------------------------------------------------------------------

namespace {

/// A glossy, normal-mapped plane (f0 = 1, no diffuse) under a quad light whose reflection the
/// camera sees, as the built-in quad-light scene has it, at a test's size.
TestScene quad_light_plane(double alpha) {
  return TestScene()
      .film(48, 48)
      .camera({0.0, 1.0, 3.0}, {0.0, 0.0, 1.0}, 50)
      .material("glossy", {{"ndf", "ggx"},
                           {"alpha", alpha},
                           {"f0", 1},
                           {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 128}, {"alpha", 0.1},
                                                   {"waves", 32}, {"max_frequency", 8}, {"seed", 2}}},
                           {"normal_map_tiling", 1}})
      .plane("glossy", {{"size", 8}, {"uv_scale", 4}})
      .light("quad", {{"position", {0.0, 2.0, -2.0}},
                      {"direction", {0.0, -2.0, 3.33}},
                      {"size", {1.5, 0.5}},
                      {"up", {0, 1, 0}},
                      {"radiance", 5},
                      {"visible", false}});
}

}  // namespace

TEST(QuadLight, GlossyPlaneReferenceIsFiniteAndConverges) {
  // Independent seeds: the 64-spp reference is not a part of the 1024-spp one.
  for (double alpha : {0.05, 0.3}) {
    SceneFixture f(quad_light_plane(alpha));
    const ReferenceFrame hi = f.reference_estimate(1024, 0, 0), lo = f.reference_estimate(64, 0, 7);
    EXPECT_EQ(hi.mean.total.count_non_finite(), 0u);
    EXPECT_EQ(lo.mean.total.count_non_finite(), 0u);
    const double e_hi = luminance(glm::vec3(hi.mean.total.mean())), e_lo = luminance(glm::vec3(lo.mean.total.mean()));
    const double noise = std::hypot(hi.relative_energy_error(), lo.relative_energy_error());
    ASSERT_GT(e_hi, 0.0) << "the quad's reflection is in view";
    EXPECT_NEAR(e_lo / e_hi, 1.0, 4 * noise) << "alpha " << alpha;
    std::printf("alpha %.2f: energy 1024 spp %.6f, 64 spp %.6f (relative noise %.2g)\n", alpha, e_hi, e_lo, noise);
  }
}

// The quad light over a glossy binomial-glints plane, with a dark disk and a dark sphere light
// (radiance 0: they add exactly 0): the quad alone lights the image, and the light kinds and counts
// and the material variant are builtin:glint-area-lights', so every program drawn here is one that
// its every-method test (tests/render/test_images.cpp) draws too, shared through the GL driver's
// shader cache (tests/test_costs.cmake). The normal-mapped default material of quad_light_plane
// is drawn by every method in builtin:gltf-showcase, and compiled with a quad light by
// Shaders.EveryMethodAndPassCompiles*.
TEST(QuadLight, EveryMethodRendersItFinite) {
  Scene scene = TestScene()
                    .film(48, 48)
                    .camera({0.0, 1.0, 3.0}, {0.0, 0.0, 1.0}, 50)
                    .material("glitter", {{"type", "binomial-glints"}, {"alpha", 0.05}, {"f0", 1}})
                    .plane("glitter", {{"size", 8}, {"uv_scale", 4}})
                    .light("quad", {{"position", {0.0, 2.0, -2.0}},
                                    {"direction", {0.0, -2.0, 3.33}},
                                    {"size", {1.5, 0.5}},
                                    {"up", {0, 1, 0}},
                                    {"radiance", 5},
                                    {"visible", false}})
                    .disk_light({0.0, 2.0, -2.0}, {0, -1, 0}, 0.3, 1, {{"visible", false}})
                    .sphere_light({0.0, 2.0, -2.0}, 0.1, 1, {{"visible", false}})
                    .scene();
  ASSERT_EQ(scene.lights.size(), 3u);
  scene.lights[1].colour = scene.lights[2].colour = glm::vec3(0.0f);
  SceneFixture f(scene);
  for (const auto& m : all_methods()) {
    const Frame img = f.method(m.id);
    EXPECT_EQ(img.total.count_non_finite(), 0u) << m.id;
    EXPECT_GT(luminance(glm::vec3(img.total.mean())), 0.0f) << m.id;
  }
}

TEST(QuadLight, BuiltinSceneReferenceIsFinite) {
  SceneFixture f(builtin_scene("quad-light", 64, 36));
  ASSERT_EQ(f.scene.lights.size(), 1u);
  EXPECT_EQ(f.scene.lights[0].kind->id, "quad");
  const Frame ref = f.reference(16);
  EXPECT_EQ(ref.total.count_non_finite(), 0u);
  EXPECT_GT(luminance(glm::vec3(ref.specular.mean())), 0.0f);
}
