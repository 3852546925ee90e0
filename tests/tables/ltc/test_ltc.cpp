// The LTC distribution (src/tables/ltc/ltc.hpp): normalisation, its sampler, the polygon integral with
// horizon clipping against direct integration of the density, and the horizon-clipped spherical
// cap of the sphere table (src/tables/ltc/ltc_sphere.hpp) at its limits and against sampling.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "tables/ltc/ltc.hpp"
#include "tables/ltc/ltc_sphere.hpp"
#include "ltc_quadrature.hpp"

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// Matrices of the fitted form and beyond: stretched, sheared, tilted, anisotropic.
std::vector<glm::dmat3> some_matrices() {
  return {glm::dmat3(1.0),
          glm::dmat3(glm::dvec3(0.5, 0.0, 0.0), glm::dvec3(0.0, 0.5, 0.0), glm::dvec3(0.0, 0.0, 1.0)),
          glm::dmat3(glm::dvec3(0.4, 0.0, -0.2), glm::dvec3(0.0, 0.7, 0.0), glm::dvec3(0.5, 0.0, 1.0)),
          glm::dmat3(glm::dvec3(0.9, 0.1, 0.0), glm::dvec3(-0.2, 0.6, 0.1), glm::dvec3(0.3, -0.4, 1.2))};
}

TEST(Ltc, TheDensityIntegratesToOneOverTheSphere) {
  for (const auto& m : some_matrices()) {
    const Ltc ltc(m);
    EXPECT_NEAR(test::integrate_sphere([&](const glm::dvec3& w) { return ltc.density(w); }, 800), 1.0, 2e-4);
  }
}

TEST(Ltc, TheInverseConstructorAndTheCosineSpaceDensityAgree) {
  for (const auto& m : some_matrices()) {
    const Ltc a(m), b = Ltc::from_inverse(glm::inverse(m));
    for (int k = 0; k < 16; ++k) {
      const glm::dvec3 w_o = sample_cosine({(k % 4 + 0.3) / 4.0, (k / 4 + 0.6) / 4.0});
      const glm::dvec3 w = glm::normalize(m * w_o);
      EXPECT_NEAR(a.density_of_cosine_direction(w_o), a.density(w), 1e-9 * a.density(w));
      EXPECT_NEAR(b.density(w), a.density(w), 1e-9 * a.density(w));
    }
  }
  EXPECT_THROW(Ltc(glm::dmat3(0.0)), std::invalid_argument);
}

TEST(Ltc, SamplesFollowTheDensity) {
  // The mean of a smooth function of the samples against its integral with the density.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01;
  for (const auto& m : some_matrices()) {
    const Ltc ltc(m);
    auto g = [](const glm::dvec3& w) { return w.x + 2.0 * w.y * w.y + w.z; };
    const double truth = test::integrate_sphere([&](const glm::dvec3& w) { return g(w) * ltc.density(w); }, 600);
    double mean = 0.0;
    constexpr int kSamples = 200000;
    for (int k = 0; k < kSamples; ++k) mean += g(ltc.sample({u01(rng), u01(rng)})) / kSamples;
    EXPECT_NEAR(mean, truth, 0.01) << "the samples' mean is ~1/sqrt(N) from the truth";
  }
}

/// A quad's corners: centre c, half edges e1, e2 (counter-clockwise about +z seen from above when
/// e1 x e2 points down, i.e. towards the shading point).
std::array<glm::dvec3, 4> quad(glm::dvec3 c, glm::dvec3 e1, glm::dvec3 e2) {
  return {c - e1 - e2, c + e1 - e2, c + e1 + e2, c - e1 + e2};
}

/// The integral of g over the directions the quad subtends: the midpoint rule on the quad itself,
/// dw = |cos at the light| dA / r^2.
template <class G>
double integrate_over_quad(const std::array<glm::dvec3, 4>& q, G&& g, int n = 800) {
  const glm::dvec3 o = q[0], a = q[1] - q[0], b = q[3] - q[0];
  const glm::dvec3 normal = glm::cross(a, b);
  const double area = glm::length(normal);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::dvec3 p = o + a * ((i + 0.5) / n) + b * ((j + 0.5) / n);
      const double r2 = glm::dot(p, p);
      const glm::dvec3 w = p / std::sqrt(r2);
      sum += g(w) * std::abs(glm::dot(w, normal)) / area / r2;
    }
  return sum * area / (static_cast<double>(n) * n);
}

TEST(Ltc, ThePolygonIntegralMatchesTheDensityIntegratedOverAQuad) {
  const std::vector<std::array<glm::dvec3, 4>> quads = {
      quad({0.2, 0.1, 1.0}, {0.4, 0.0, 0.0}, {0.0, -0.3, 0.0}),   // above, facing down
      quad({1.0, 0.0, 0.8}, {0.0, 0.5, 0.0}, {-0.2, 0.0, 0.3}),   // tilted
      quad({0.6, 0.3, 0.1}, {0.0, 0.4, 0.0}, {0.0, 0.0, -0.5}),   // crossing the horizon
      quad({-0.7, 0.0, -0.2}, {0.0, -0.6, 0.0}, {0.1, 0.0, 0.6}), // crossing it, behind the view
  };
  for (const auto& m : some_matrices()) {
    const Ltc ltc(m);
    for (const auto& q : quads) {
      const double clipped = integrate_over_quad(q, [&](const glm::dvec3& w) { return w.z > 0.0 ? ltc.density(w) : 0.0; });
      const double whole = integrate_over_quad(q, [&](const glm::dvec3& w) { return ltc.density(w); });
      EXPECT_NEAR(std::abs(ltc_polygon_integral(ltc, q, true)), clipped, 2e-4 + 1e-4 * clipped);
      EXPECT_NEAR(std::abs(ltc_polygon_integral(ltc, q, false)), whole, 2e-4 + 1e-4 * whole);
    }
  }
}

TEST(Ltc, ThePolygonIntegralIsSignedByTheWinding) {
  auto q = quad({0.1, 0.2, 1.0}, {0.5, 0.0, 0.0}, {0.0, 0.5, 0.0});  // counter-clockwise seen from above
  const Ltc ltc(some_matrices()[2]);
  const double forward = ltc_polygon_integral(ltc, q);
  std::reverse(q.begin(), q.end());
  EXPECT_GT(forward, 0.0);
  EXPECT_NEAR(ltc_polygon_integral(ltc, q), -forward, 1e-12);
}

TEST(Ltc, AnInfinitePlaneAboveHasFormFactorOneAndOneBelowZero) {
  const auto above = quad({0.0, 0.0, 1.0}, {1e5, 0.0, 0.0}, {0.0, 1e5, 0.0});
  EXPECT_NEAR(clipped_polygon_form_factor(above), 1.0, 1e-4);
  const auto below = quad({0.0, 0.0, -1.0}, {1e5, 0.0, 0.0}, {0.0, 1e5, 0.0});
  EXPECT_EQ(clipped_polygon_form_factor(below), 0.0);
  // Half of it (x > 0): one half by symmetry.
  const auto half = quad({5e4, 0.0, 1.0}, {5e4, 0.0, 0.0}, {0.0, 1e5, 0.0});
  EXPECT_NEAR(clipped_polygon_form_factor(half), 0.5, 1e-4);
  EXPECT_EQ(clip_to_upper_half_space(below).size(), 0u);
}

TEST(Ltc, DiskAndSphereIntegralsMatchTheDensityIntegratedOverThem) {
  const Ltc ltc(some_matrices()[2]);
  // A disk by quadrature over its area (polar grid), dw = |cos| dA / r^2; with the surface horizon.
  auto disk_by_quadrature = [&](glm::dvec3 c, glm::dvec3 n, double radius) {
    n = glm::normalize(n);
    const glm::dvec3 e1 = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.9, 0.1))), e2 = glm::cross(n, e1);
    constexpr int kR = 600, kPhi = 1200;
    double sum = 0.0;
    for (int a = 0; a < kR; ++a)
      for (int b = 0; b < kPhi; ++b) {
        const double rho = radius * (a + 0.5) / kR, phi = 2.0 * kPi * (b + 0.5) / kPhi;
        const glm::dvec3 p = c + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const double r2 = glm::dot(p, p);
        const glm::dvec3 w = p / std::sqrt(r2);
        if (w.z > 0.0) sum += ltc.density(w) * std::abs(glm::dot(w, n)) / r2 * rho;
      }
    return sum * (radius / kR) * (2.0 * kPi / kPhi);
  };
  for (auto [c, n, r] : {std::tuple{glm::dvec3(0.3, 0.1, 1.0), glm::dvec3(0.0, 0.2, -1.0), 0.4},
                         std::tuple{glm::dvec3(0.8, -0.2, 0.1), glm::dvec3(-1.0, 0.0, 0.3), 0.5}}) {  // crossing the horizon
    const double truth = disk_by_quadrature(c, n, r);
    EXPECT_NEAR(ltc_disk_integral(ltc, c, n, r), truth, 2e-4 * truth + 1e-5);
  }
  // A sphere: its cap in the cap's own polar coordinates.
  for (auto [c, r] : {std::pair{glm::dvec3(0.2, 0.3, 1.5), 0.6}, std::pair{glm::dvec3(1.0, 0.0, 0.2), 0.5}}) {
    const glm::dvec3 axis = glm::normalize(c);
    const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), axis)), t2 = glm::cross(axis, t1);
    const double truth = test::integrate_band(
        [&](const glm::dvec3& w) {
          const glm::dvec3 d = w.x * t1 + w.y * t2 + w.z * axis;
          return d.z > 0.0 ? ltc.density(d) : 0.0;
        },
        0.0, std::asin(r / glm::length(c)), 1500);
    EXPECT_NEAR(ltc_sphere_integral(ltc, c, r), truth, 2e-4 * truth + 1e-5);
  }
  EXPECT_THROW((void)ltc_sphere_integral(ltc, glm::dvec3(0, 0, 1), 2.0), std::invalid_argument);
}

/// A cap of angular radius sigma about the direction with elevation cosine z.
double cap_by_quadrature(double z, double sigma) {
  const glm::dvec3 centre(std::sqrt(1.0 - z * z), 0.0, z);
  const double cos_sigma = std::cos(sigma);
  // Integrate in the cap's own polar coordinates (the cap is a band there).
  const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre)), t2(0, 1, 0);
  return test::integrate_band(
             [&](const glm::dvec3& w) {
               const glm::dvec3 d = w.x * t1 + w.y * t2 + w.z * centre;
               return std::max(0.0, d.z);
             },
             0.0, std::acos(cos_sigma), 1200) /
         kPi;
}

TEST(SphereCap, IsTheUnclippedFormFactorAboveTheHorizonAndZeroBelow) {
  for (double sigma : {0.05, 0.4, 0.9, 1.5}) {
    const double f = std::sin(sigma) * std::sin(sigma);
    for (double omega : {0.0, 0.3, 0.7, 1.2}) {
      if (omega + sigma > 0.5 * kPi) continue;
      EXPECT_NEAR(clipped_cap_ratio(std::cos(omega), f), std::cos(omega), 1e-12) << sigma << " " << omega;
      EXPECT_NEAR(clipped_cap_ratio(std::cos(kPi - omega), f), 0.0, 1e-12) << sigma << " " << omega;
    }
  }
  EXPECT_EQ(clipped_cap_ratio(0.3, 0.0), 0.3);
  EXPECT_EQ(clipped_cap_ratio(-0.3, 0.0), 0.0);
}

TEST(SphereCap, MatchesQuadratureWhereTheHorizonCutsIt) {
  for (double sigma : {0.2, 0.6, 1.0, 1.5707}) {
    double previous = 0.0;
    for (double z : {-0.9, -0.5, -0.1, 0.0, 0.15, 0.5, 0.95}) {
      const double f = clipped_cap_form_factor(z, std::sin(sigma) * std::sin(sigma));
      EXPECT_NEAR(f, cap_by_quadrature(z, sigma), 2e-6) << sigma << " " << z;
      EXPECT_GE(f, previous) << "a higher centre never sees less";
      previous = f;
    }
  }
}

}  // namespace
}  // namespace glintlab
