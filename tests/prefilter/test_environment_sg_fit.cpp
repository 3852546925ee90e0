// The spherical Gaussian fit of an environment (src/prefilter/environment_sg_fit.hpp; Deng et al.
// 2022 sec. 5.4): the SG's closed forms against quadrature, eq. 8's support angle, the fit
// recovering a map made of known lobes, a uniform map, the error falling as lobes are added on the
// studio environment with its power kept, and bad counts refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "prefilter/environment_sg_fit.hpp"
#include "scene/lights/environment_studio.hpp"

using namespace glintlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A map whose texels are `f` at their centres (the fit reads texel values, so a smooth f is
/// recovered to the resolution's sampling).
template <typename F>
EnvironmentMap map_of(int height, F&& f) {
  EnvironmentMap map{Image(2 * height, height), "test"};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x)
      map.radiance.at(x, y) = glm::vec3(f(environment_direction_precise((x + 0.5) / (2 * height), (y + 0.5) / height)));
  return map;
}

}  // namespace

TEST(SphericalGaussian, ClosedFormsAgreeWithQuadrature) {
  // The integral over the sphere by a midpoint rule in (cos theta, phi) about the lobe's axis.
  const SphericalGaussian g{glm::normalize(glm::dvec3(0.3, 0.8, -0.5)), 7.5, {2.0, 1.0, 0.5}};
  const int n = 2000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += std::exp(g.sharpness * ((-1.0 + (i + 0.5) * 2.0 / n) - 1.0)) * (2.0 / n);
  EXPECT_NEAR(g.integral().x, 2.0 * 2.0 * kPi * sum, 1e-5 * g.integral().x);  // the rule's h^2 lambda^2 / 24
  EXPECT_DOUBLE_EQ(g.integral().y / g.integral().z, 2.0);
  // Eq. 8: the luminance at the support angle is epsilon; none above the amplitude, all of the sphere
  // when even the antipode exceeds it.
  const double lum = 0.2126 * 2.0 + 0.7152 * 1.0 + 0.0722 * 0.5;
  for (double epsilon : {0.01, 0.1, 1.0}) {
    const double theta = g.support_angle(epsilon);
    EXPECT_NEAR(lum * std::exp(g.sharpness * (std::cos(theta) - 1.0)), epsilon, 1e-9) << epsilon;
  }
  EXPECT_EQ(g.support_angle(5.0), 0.0);
  // The cone of the lobe's solid angle: 2 pi (1 - cos) = Omega.
  const double s = g.cone_half_angle_sine();
  EXPECT_NEAR(2.0 * kPi * (1.0 - std::sqrt(1.0 - s * s)), g.solid_angle(), 1e-12);
  EXPECT_NEAR(SphericalGaussian({0, 1, 0}, 0.1, glm::dvec3(1.0)).support_angle(0.5), kPi, 1e-12);
}

TEST(SphericalGaussianFit, RecoversAMapMadeOfItsOwnLobes) {
  // Three lobes on the lattice's axes at one of the grid's sharpnesses (lambda_0 = K / pi): the
  // basis holds the map exactly, so the nonnegative fit must find it.
  const int k = 32;
  const std::vector<glm::dvec3> axes = fibonacci_directions(k);
  const std::vector<SphericalGaussian> truth = {{axes[3], k / kPi, {4.0, 2.0, 1.0}},
                                                {axes[17], k / kPi, {0.5, 0.5, 3.0}},
                                                {axes[28], k / kPi, {1.0, 0.0, 0.0}}};
  const EnvironmentMap map = map_of(64, [&](const glm::dvec3& d) {
    glm::dvec3 sum(0.0);
    for (const auto& g : truth) sum += g.value(d);
    return sum;
  });
  const SphericalGaussianFit fit = fit_spherical_gaussians(map, k, 64);
  std::printf("three known lobes: relative error %.2e\n", fit.relative_error);
  EXPECT_LT(fit.relative_error, 1e-4);
  ASSERT_EQ(fit.lobes.size(), static_cast<std::size_t>(k));
  EXPECT_NEAR(fit.lobes[3].sharpness, k / kPi, 1e-9);
  for (int j = 0; j < k; ++j) {
    glm::dvec3 expected(0.0);
    for (const auto& g : truth)
      if (glm::dot(g.axis, axes[j]) > 0.999999) expected = g.amplitude;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fit.lobes[j].amplitude[c], expected[c], 1e-3) << "lobe " << j;
  }
  // Lobes are chosen by their luminance's integral: one sharpness, so in proportion to the amplitudes'.
  const std::vector<double> p = fit.lobe_probabilities();
  const auto lum = [](const glm::dvec3& a) { return 0.2126 * a.r + 0.7152 * a.g + 0.0722 * a.b; };
  const double total = lum(truth[0].amplitude) + lum(truth[1].amplitude) + lum(truth[2].amplitude);
  EXPECT_NEAR(p[3], lum(truth[0].amplitude) / total, 1e-4);
  EXPECT_NEAR(p[17], lum(truth[1].amplitude) / total, 1e-4);
}

TEST(SphericalGaussianFit, AUniformMapKeepsItsPower) {
  const EnvironmentMap map = uniform_environment_map(glm::vec3(1.0f, 0.5f, 0.25f));
  const SphericalGaussianFit fit = fit_spherical_gaussians(map, 64, 32);
  glm::dvec3 power(0.0);
  for (const auto& g : fit.lobes) power += g.integral();
  std::printf("uniform map, 64 lobes: relative error %.3f, power %.4f of 4 pi\n", fit.relative_error, power.x / (4 * kPi));
  EXPECT_LT(fit.relative_error, 0.05);  // lobes no wider than their share of the sphere ripple
  EXPECT_NEAR(power.x / (4 * kPi), 1.0, 0.02);
  EXPECT_NEAR(power.y / power.x, 0.5, 1e-3);
}

TEST(SphericalGaussianFit, TheErrorFallsAsLobesAreAdded) {
  // The studio map (sky, soft boxes, a 1.5-degree sun): its sun is finer than any lobe here and holds
  // most of the map's L2 norm, so the error stays large, but more lobes resolve more of it.
  const EnvironmentMap studio = studio_environment_map(64);
  double previous = HUGE_VAL;
  for (int k : {8, 32, 128}) {
    const SphericalGaussianFit fit = fit_spherical_gaussians(studio, k, 32);
    glm::dvec3 power(0.0), map_power(0.0);
    for (const auto& g : fit.lobes) power += g.integral();
    for (int y = 0; y < studio.radiance.height(); ++y)
      for (int x = 0; x < studio.radiance.width(); ++x)
        map_power += glm::dvec3(studio.radiance.at(x, y)) * environment_row_solid_angle(y, studio.radiance.height());
    std::printf("studio, %d lobes: relative error %.3f, lambda %.1f, power %.3f of the map's\n", k, fit.relative_error,
                fit.lobes.back().sharpness, power.y / map_power.y);
    EXPECT_LT(fit.relative_error, previous) << k << " lobes";
    EXPECT_NEAR(power.y / map_power.y, 1.0, 1e-4) << k << " lobes: the fit keeps the map's power";
    EXPECT_LT(fit.relative_error, 1.0);
    previous = fit.relative_error;
  }
}

TEST(SphericalGaussianFit, ASunIsALobeOfItsOwnAndTheSkyKeepsItsLight) {
  // A uniform sky of radiance 1 and a sun of half a degree holding 20 times the sky's power: the
  // sun's lobe takes the sun's power at the sun's direction, and the other lobes the sky's, which
  // they give back in every direction (the sharp map's L2 fit alone put the power the sun's
  // lobes overshoot by into them and took it from the sky: near 0 far from the sun).
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.4, 0.6, -0.7));
  const double sun_cos = std::cos(0.5 * kPi / 180.0), sun_solid_angle = 2.0 * kPi * (1.0 - sun_cos);
  const double sun_radiance = 20.0 * 4.0 * kPi / sun_solid_angle;
  const int height = 512;
  EnvironmentMap map = map_of(height, [](const glm::dvec3&) { return glm::dvec3(1.0); });
  double sun_power = 0.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x)
      if (glm::dot(environment_direction_precise((x + 0.5) / (2 * height), (y + 0.5) / height), sun) > sun_cos) {
        map.radiance.at(x, y) = glm::vec3(static_cast<float>(sun_radiance));
        sun_power += (sun_radiance - 1.0) * environment_row_solid_angle(y, height);
      }
  const SphericalGaussianFit fit = fit_spherical_gaussians(map, 32, 64);
  ASSERT_EQ(fit.peaks, 1);
  const SphericalGaussian& peak = fit.lobes.front();
  std::printf("a sun: its lobe %.4f of its power, %.3f degrees off, sharpness %.0f; the sky's lobes give %.3f .. %.3f, "
              "relative error %.3f\n",
              peak.integral().x / (sun_power + sun_solid_angle), std::acos(std::min(glm::dot(peak.axis, sun), 1.0)) * 180 / kPi,
              peak.sharpness, fit.without_peaks().radiance(-sun).x, fit.without_peaks().radiance(glm::dvec3(0, -1, 0)).x,
              fit.relative_error);
  EXPECT_NEAR(peak.integral().x / (sun_power + sun_solid_angle), 1.0, 0.02);  // the sun's texels, sky and all
  EXPECT_GT(glm::dot(peak.axis, sun), std::cos(0.2 * kPi / 180.0));
  for (const glm::dvec3& d : {-sun, glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0)})
    EXPECT_NEAR(fit.without_peaks().radiance(d).x, 1.0, 0.1) << d.x << ", " << d.y << ", " << d.z;
}

TEST(SphericalGaussianFit, RefusesCountsAndGridsOutOfRange) {
  const EnvironmentMap map = uniform_environment_map(glm::vec3(1.0f));
  EXPECT_THROW(fit_spherical_gaussians(map, 0), InputError);
  EXPECT_THROW(fit_spherical_gaussians(map, 1025), InputError);
  EXPECT_THROW(fit_spherical_gaussians(map, 8, 1), InputError);
  EXPECT_THROW(fit_spherical_gaussians(map, 8, map.radiance.height() + 1), InputError);
}
