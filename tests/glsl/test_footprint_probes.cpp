// deng2022's isotropic probes along an anisotropic footprint's major axis
// (shaders/glints/normal-map/footprint_probes.glsl) on the GL device: the probes' mixture, sigma^2 I
// plus the probes' weighted scatter about the centre, has the footprint's variance along its major
// axis always, and its whole covariance whenever the probes allowed suffice; past them only the
// minor axis widens. Probes are at most 2 sigma apart, their weights sum to 1, and one probe is the
// isotropic footprint of the same area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gl_fixture.hpp"

using namespace glintlab::test;

namespace {

struct Case {
  glm::dmat2 sigma_p;  // texels^2
  double min_sigma;
  int max_probes;
};

// Per case: (mixture covariance 00, 01, 11, spacing / sigma) and (weight sum, probes, sigma, 0).
std::pair<std::vector<glm::vec4>, std::vector<glm::vec4>> probe(const std::vector<Case>& cases) {
  std::vector<glm::vec4> a, b;
  for (const Case& c : cases) {
    a.emplace_back(c.sigma_p[0][0], c.sigma_p[0][1], c.sigma_p[1][1], c.min_sigma);
    b.emplace_back(static_cast<float>(c.max_probes), 0.0f, 0.0f, 0.0f);
  }
  const std::string includes = "#include \"glints/normal-map/footprint_probes.glsl\"\n";
  auto moments = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  FootprintProbes p = footprintProbes(vec2(3.5, -2.25), mat2(a.x, a.y, a.y, a.z), a.w, int(b.x));
  mat2 scatter = mat2(0.0);
  ProbeWeights w = p.weights;
  for (int j = 0; j < p.count; ++j) {
    vec2 t = probeCentre(p, j) - p.centre;
    scatter += nextProbeWeight(w) * outerProduct(t, t);
  }
  mat2 mixture = mat2(p.sigma * p.sigma) + scatter;
  return vec4(mixture[0][0], mixture[0][1], mixture[1][1], length(p.step) / p.sigma);
})", a, b);
  auto counts = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  FootprintProbes p = footprintProbes(vec2(3.5, -2.25), mat2(a.x, a.y, a.y, a.z), a.w, int(b.x));
  float sum = 0.0;
  ProbeWeights w = p.weights;
  for (int j = 0; j < p.count; ++j) sum += nextProbeWeight(w);
  return vec4(sum, float(p.count), p.sigma, 0.0);
})", a, b);
  return {moments, counts};
}

}  // namespace

TEST(FootprintProbes, TheMixtureIsTheFootprintAlongItsMajorAxisAndWithinTheProbesAllowedEverywhere) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Case> cases;
  for (int i = 0; i < 400; ++i) {
    const double minor = std::exp2(4.0 * unit(rng) - 1.0), ratio = std::exp2(5.0 * unit(rng));  // anisotropy 1 .. 32
    const double angle = 6.2831853 * unit(rng);
    const glm::dvec2 axis(std::cos(angle), std::sin(angle)), across(-axis.y, axis.x);
    const glm::dmat2 sigma_p = minor * minor * (glm::outerProduct(across, across) + ratio * ratio * glm::outerProduct(axis, axis));
    cases.push_back({sigma_p, std::array{0.25, 1.0, 3.0}[i % 3], std::array{1, 4, 8, 16}[(i / 3) % 4]});
  }
  const auto [moments, counts] = probe(cases);
  int exact = 0, capped = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const glm::dmat2 mixture(moments[i].x, moments[i].y, moments[i].y, moments[i].z);
    const double sigma = counts[i].z;
    const double trace = c.sigma_p[0][0] + c.sigma_p[1][1], det = glm::determinant(c.sigma_p);
    const double major = 0.5 * trace + std::sqrt(std::max(0.25 * trace * trace - det, 0.0)), minor = det / major;
    SCOPED_TRACE(testing::Message() << "case " << i << ": major " << major << ", minor " << minor << ", min sigma "
                                    << c.min_sigma << ", probes at most " << c.max_probes);
    EXPECT_NEAR(counts[i].x, 1.0, 1e-5) << "the weights' sum";
    EXPECT_LE(counts[i].y, c.max_probes);
    EXPECT_GE(sigma, c.min_sigma * (1 - 1e-6));
    if (c.max_probes == 1) {  // the isotropic footprint of the same area
      EXPECT_NEAR(sigma, std::max(std::pow(det, 0.25), c.min_sigma), 1e-4 * sigma);
      continue;
    }
    if (counts[i].y > 1) {
      EXPECT_LE(moments[i].w, 2.0 + 1e-4) << "probes more than 2 sigma apart";
    }
    const double floor2 = c.min_sigma * c.min_sigma;
    if (major <= floor2) {  // the pyramid's first level: one probe of it
      EXPECT_EQ(counts[i].y, 1);
      continue;
    }
    // Along the major axis the mixture is the footprint; across it, never narrower.
    const glm::dvec2 eigen = glm::normalize(std::abs(c.sigma_p[0][1]) > 1e-12 ? glm::dvec2(c.sigma_p[0][1], major - c.sigma_p[0][0])
                                                                               : (c.sigma_p[0][0] >= c.sigma_p[1][1] ? glm::dvec2(1, 0) : glm::dvec2(0, 1)));
    const glm::dvec2 across(-eigen.y, eigen.x);
    EXPECT_NEAR(glm::dot(eigen, mixture * eigen), major, 2e-4 * major);
    EXPECT_GE(glm::dot(across, mixture * across), std::max(minor, floor2) * (1 - 2e-4));
    EXPECT_NEAR(glm::dot(eigen, mixture * across), 0.0, 2e-4 * major);
    // With the probes allowed enough (sigma no wider than the minor axis or the first level), the
    // whole covariance; else sigma widened, spaced exactly 2 sigma apart.
    const double sigma_minor = std::max(std::sqrt(minor), c.min_sigma);
    if (sigma <= sigma_minor * (1 + 1e-5)) {
      EXPECT_NEAR(glm::dot(across, mixture * across), std::max(minor, floor2), 2e-4 * major);
      ++exact;
    } else {
      EXPECT_EQ(counts[i].y, c.max_probes);
      EXPECT_NEAR(moments[i].w, 2.0, 1e-3);
      ++capped;
    }
  }
  EXPECT_GT(exact, 100);
  EXPECT_GT(capped, 30);
}
