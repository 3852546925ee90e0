// The point-process glinty NDF (shaders/glints/point-process/ndf.glsl; Kemppinen et al. 2025,
// docs/methods.md#kemppinen2025) on the GL device: its angular map against its inverse and its
// Jacobian against finite areas; its mean over the surface against the base NDF (GGX and
// Beckmann, isotropic and anisotropic, footprints of a fraction of a facet to thousands), its
// spread shrinking as the footprint grows; its sampler's histogram against its density
// (chi-square) and the sampled estimate of the NDF's integral against quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "chi_square.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(#include "glints/point-process/ndf.glsl"
)";

// ln N = 10: about 148 facets per uv unit along each axis.
constexpr double kLogDensity = 10.0;
const double kSpacing = std::exp(-0.5 * kLogDensity);

struct Material {
  int kind;  // 0 GGX, 1 Beckmann
  glm::vec2 alpha;
  float sigma;
};

// GLSL building the footprint of uv a.xy with covariance (a.z^2) I from `m`.
std::string footprint_code(const Material& m) {
  char text[256];
  std::snprintf(text, sizeof text,
                "PointProcessFootprint footprintOf(vec4 a) { return pointProcessFootprint(a.xy, mat2(a.z * a.z), "
                "%.9g, %.9g, %d, vec2(%.9g, %.9g)); }\n",
                kLogDensity, double(m.sigma), m.kind, double(m.alpha.x), double(m.alpha.y));
  return text;
}

double base_ndf(const Material& m, glm::dvec3 h) {
  const double ax = m.alpha.x, ay = m.alpha.y;
  if (m.kind == 0) {
    const double e = h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z;
    return 1.0 / (M_PI * ax * ay * e * e);
  }
  const double c2 = h.z * h.z;
  return std::exp(-(h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay)) / c2) / (M_PI * ax * ay * c2 * c2);
}

glm::dvec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(PointProcessGlints, TheAngularMapInvertsAndItsJacobianIsTheAreaRatio) {
  const Material m{0, {0.35f, 0.15f}, 0.02f};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 256; ++i) {
    const glm::dvec3 h = direction(std::acos(std::sqrt(u(rng))) * 0.98, 2 * M_PI * u(rng));
    a.emplace_back(h.x, h.y, h.z, 0.0f);
    b.emplace_back(m.alpha.x, m.alpha.y, 1e-3f, 0.0f);
  }
  // Back and forth; and the solid angle of the small triangle x, x + e ex, x + e ey mapped to h,
  // against (e^2 / 2) / J.
  const auto r = evaluate_glsl(kIncludes, R"(
float triangleSolidAngle(vec3 p, vec3 q, vec3 r) {
  return 2.0 * atan(abs(dot(p, cross(q, r))), 1.0 + dot(p, q) + dot(q, r) + dot(r, p));
}
vec4 evaluate(vec4 a, vec4 b) {
  vec3 h = a.xyz;
  vec2 x = pointProcessAngular(h, b.xy);
  vec3 back = pointProcessDirection(x, b.xy);
  float e = b.z;
  float omega = triangleSolidAngle(back, pointProcessDirection(x + vec2(e, 0.0), b.xy),
                                   pointProcessDirection(x + vec2(0.0, e), b.xy));
  vec3 middle = pointProcessDirection(x + vec2(e / 3.0), b.xy);  // the triangle's centroid
  return vec4(distance(back, h), omega * pointProcessAngularJacobian(middle, b.xy) / (0.5 * e * e), x);
})",
                               a, b);
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_LT(r[i].x, 2e-5) << i;
    EXPECT_NEAR(r[i].y, 1.0, 5e-3) << i;  // fp32 areas of a 1e-3 triangle
    EXPECT_LE(std::hypot(r[i].z - 0.5, r[i].w - 0.5), 0.5 + 1e-6) << i;
  }
}

// D / D_base at `h` over `count` random points of the surface, for a footprint of standard
// deviation `sigma_facets` facet spacings.
std::vector<double> ndf_over_surface(const Material& m, glm::dvec3 h, double sigma_facets, int count,
                                     std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 50.0);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < count; ++i) {
    a.emplace_back(u(rng), u(rng), sigma_facets * kSpacing, 0.0f);
    b.emplace_back(h.x, h.y, h.z, 0.0f);
  }
  const auto r = evaluate_glsl(std::string(kIncludes) + footprint_code(m),
                               "vec4 evaluate(vec4 a, vec4 b) { return vec4(pointProcessNdf(footprintOf(a), "
                               "normalize(b.xyz)), 0.0, 0.0, 0.0); }",
                               a, b);
  std::vector<double> out;
  const double base = base_ndf(m, h);
  for (const auto& v : r) out.push_back(v.x / base);
  return out;
}

struct MeanAndSpread {
  double mean, standard_error, spread;
};
MeanAndSpread statistics(const std::vector<double>& v) {
  double sum = 0, sum2 = 0;
  for (double x : v) {
    sum += x;
    sum2 += x * x;
  }
  const double n = static_cast<double>(v.size()), mean = sum / n, var = std::max(sum2 / n - mean * mean, 0.0);
  return {mean, std::sqrt(var / n), std::sqrt(var)};
}

TEST(PointProcessGlints, ItsMeanIsTheBaseNdfAndItsSpreadShrinksAsTheFootprintGrows) {
  const std::vector<Material> materials = {
      {0, {0.3f, 0.3f}, 0.02f}, {1, {0.5f, 0.5f}, 0.02f}, {0, {0.4f, 0.12f}, 0.05f}};
  // Away from Beckmann's far tail, where D_base is tiny and a facet's glint (of constant peak) is
  // rare and bright: there 4096 points of the surface are too few for the mean's heavy tail.
  for (const Material& m : materials)
    for (const double theta : {0.0, 0.35, 0.7}) {
      const glm::dvec3 h = direction(theta, 0.6);
      double previous_spread = std::numeric_limits<double>::infinity();
      for (const double sigma_facets : {0.3, 3.0, 30.0, 300.0}) {
        const auto s = statistics(ndf_over_surface(m, h, sigma_facets, 4096, 11));
        SCOPED_TRACE("kind " + std::to_string(m.kind) + ", alpha " + std::to_string(m.alpha.x) + "x" +
                     std::to_string(m.alpha.y) + ", theta " + std::to_string(theta) + ", footprint " +
                     std::to_string(sigma_facets) + " facets: mean " + std::to_string(s.mean) + " +- " +
                     std::to_string(s.standard_error) + ", spread " + std::to_string(s.spread));
        // Unbiased at every footprint (the visited cells' remainder enters as its expectation).
        EXPECT_NEAR(s.mean, 1.0, 4.0 * s.standard_error + 2e-3);
        // Glints average out as the footprint holds more facets: D tends to D_base.
        EXPECT_LT(s.spread, 0.7 * previous_spread);
        previous_spread = s.spread;
      }
      EXPECT_LT(previous_spread, 0.1);
    }
}

// The sampler on a glinty footprint (`sigma_facets` facet spacings): its histogram over bins of
// the angular square against its density (the failed draws a bin of their own), and the mean of
// D cos / pdf against the quadrature of D cos.
void expect_sampler_draws_its_density(const Material& m, double sigma_facets, std::uint32_t seed) {
  const glm::vec4 where(17.3f, 4.1f, static_cast<float>(sigma_facets * kSpacing), 0.0f);
  const std::string includes = std::string(kIncludes) + footprint_code(m);
  // Samples: the angular point of each drawn h (or a failure), and D cos / pdf.
  constexpr int kSamples = 1 << 17;
  std::vector<glm::vec4> a(kSamples, where), b;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < kSamples; ++i) b.emplace_back(u(rng), u(rng), 0.0f, 0.0f);
  const auto drawn = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  PointProcessFootprint f = footprintOf(a);
  vec3 h = pointProcessSampleNormal(f, b.xy);
  if (h.z <= 0.0) return vec4(-1.0);
  float pdf = pointProcessNormalPdf(f, h);
  return vec4(pointProcessAngular(h, f.alpha), pointProcessNdf(f, h) * h.z / pdf, 1.0);
})",
                                   a, b);
  // The density per bin of a 32 x 32 grid of the square, by 8 x 8 midpoints per bin (lobes of at
  // least a few midpoints: the materials keep D_base, and so the lobes, away from underflow); and the
  // integral of D cos over the hemisphere by the same quadrature (in x: D cos / J).
  constexpr int kBins = 32, kSub = 8;
  std::vector<glm::vec4> qa, qb;
  for (int by = 0; by < kBins; ++by)
    for (int bx = 0; bx < kBins; ++bx)
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          qa.push_back(where);
          qb.emplace_back((bx + (sx + 0.5f) / kSub) / kBins, (by + (sy + 0.5f) / kSub) / kBins, 0.0f, 0.0f);
        }
  const auto density = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  PointProcessFootprint f = footprintOf(a);
  vec3 h = pointProcessDirection(b.xy, f.alpha);
  if (h.z <= 0.0) return vec4(0.0);
  float J = pointProcessAngularJacobian(h, f.alpha);
  return vec4(pointProcessNormalPdf(f, h) / J, pointProcessNdf(f, h) * h.z / J, 0.0, 0.0);
})",
                                     qa, qb);
  const double cell = 1.0 / (double(kBins) * kSub * kBins * kSub);
  std::vector<double> expected(kBins * kBins + 1, 0.0), observed(kBins * kBins + 1, 0.0);
  double integral = 0;
  for (std::size_t i = 0; i < density.size(); ++i) {
    expected[i / (kSub * kSub)] += density[i].x * cell * kSamples;
    integral += density[i].y * cell;
  }
  double drawn_total = 0;
  for (double e : expected) drawn_total += e;
  expected.back() = std::max(kSamples - drawn_total, 0.0);  // failed draws
  double estimate = 0, estimate2 = 0;
  for (const auto& s : drawn) {
    if (s.w < 0.0f) {
      observed.back() += 1;
      continue;
    }
    const int bx = std::min(kBins - 1, static_cast<int>(s.x * kBins)), by = std::min(kBins - 1, static_cast<int>(s.y * kBins));
    observed[by * kBins + bx] += 1;
    estimate += s.z;
    estimate2 += double(s.z) * s.z;
  }
  const ChiSquare c = chi_square(observed, expected);
  EXPECT_TRUE(c.passes(2)) << "chi2 " << c.chi2 << ", dof " << c.dof << ", p " << c.p;
  // The estimate of the integral of D cos (failed draws count 0) against the quadrature.
  const double mean = estimate / kSamples, error = std::sqrt((estimate2 / kSamples - mean * mean) / kSamples);
  EXPECT_NEAR(mean, integral, 4 * error + 1e-3 * integral) << "quadrature " << integral;
  // A glinty footprint: the realisation's integral is not 1, but near it.
  EXPECT_NEAR(integral, 1.0, 0.5);
}

TEST(PointProcessGlints, TheSamplerDrawsItsOwnDensityAndEstimatesTheNdfsIntegral) {
  expect_sampler_draws_its_density({0, {0.3f, 0.3f}, 0.03f}, 2.0, 8);
  expect_sampler_draws_its_density({1, {0.5f, 0.3f}, 0.03f}, 1.0, 9);
}

}  // namespace
