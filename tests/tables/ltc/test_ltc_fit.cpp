// The LTC targets and fitter (src/tables/ltc/ltc_targets.hpp, ltc_fit.hpp), on a few cells fitted here:
// the samplers against their pdfs, the magnitudes and the total NDF against quadrature, the
// fitted lobe's normalisation and fit error, isotropy at normal incidence, Schlick's split, and
// a small grid's determinism across thread counts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "tables/ltc/ltc_fit.hpp"
#include "tables/ltc/ltc_table.hpp"
#include "ltc_quadrature.hpp"

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;
const LtcTargetKind kKinds[] = {LtcTargetKind::Ggx, LtcTargetKind::Ndf};

const char* name(LtcTargetKind k) { return k == LtcTargetKind::Ggx ? "ggx" : "ndf"; }

/// The lobe's integral over the upper hemisphere by quadrature, fine near its peak: the band
/// around the reflected direction is integrated on its own dense grid.
double lobe_integral(const LtcTarget& t, double weight(const LtcTarget&, const glm::dvec3&)) {
  auto g = [&](const glm::dvec3& l) { return t.evaluate(l).value * weight(t, l); };
  return test::integrate_hemisphere(g, 1000);
}
double one(const LtcTarget&, const glm::dvec3&) { return 1.0; }
double schlick(const LtcTarget& t, const glm::dvec3& l) {
  return std::pow(1.0 - glm::dot(t.view(), glm::normalize(t.view() + l)), 5.0);
}

TEST(LtcTargets, TheTotalNdfIsTheIntegralOfD) {
  for (double alpha : {0.05, 0.2, 0.5, 0.9, 1.0}) {
    // D is isotropic: 2 pi int D sin(theta) d theta, midpoints in theta (fine enough for the peak).
    constexpr int kSteps = 200000;
    double quadrature = 0.0;
    for (int k = 0; k < kSteps; ++k) {
      const double theta = 0.5 * kPi * (k + 0.5) / kSteps;
      quadrature += 2.0 * kPi * ggx_ndf({std::sin(theta), 0.0, std::cos(theta)}, alpha) * std::sin(theta) * 0.5 * kPi / kSteps;
    }
    EXPECT_NEAR(ggx_total_ndf(alpha), quadrature, 1e-4 * quadrature) << alpha;
    EXPECT_NEAR(ggx_ndf_cone_mass(INFINITY, alpha), ggx_total_ndf(alpha), 1e-12);
    EXPECT_NEAR(ggx_ndf_cone_mass(1e12, alpha), ggx_total_ndf(alpha), 1e-6);
  }
  EXPECT_NEAR(ggx_total_ndf(1.0), 2.0, 1e-12) << "D = 1/pi over the hemisphere";
  EXPECT_NEAR(ggx_total_ndf(1e-4), 1.0, 1e-6) << "a mirror: the cosine hardly matters";
}

TEST(LtcTargets, EachSamplersPdfIntegratesToOneAndMatchesItsSamples) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01;
  for (LtcTargetKind kind : kKinds)
    for (double alpha : {0.3, 0.7})
      for (double cos_theta : {1.0, 0.6, 0.2}) {
        const LtcTarget t(kind, alpha, cos_theta);
        // (The ndf pdf has an integrable 1/|v + l| peak at l = -v, where h lies on the horizon,
        // which the quadrature underestimates by a few 1e-3.)
        EXPECT_NEAR(test::integrate_sphere([&](const glm::dvec3& l) { return t.evaluate(l).pdf; }, 1000), 1.0, 6e-3)
            << name(kind) << " " << alpha << " " << cos_theta;
        // E[g(l)] over the sampler against the integral of g times the pdf.
        auto g = [](const glm::dvec3& l) { return l.x + l.z * l.z; };
        const double truth = test::integrate_sphere([&](const glm::dvec3& l) { return g(l) * t.evaluate(l).pdf; }, 1000);
        double mean = 0.0;
        constexpr int kSamples = 100000;
        for (int k = 0; k < kSamples; ++k)
          mean += g(t.reflect_view(t.sample_half_vector({u01(rng), u01(rng)}))) / kSamples;
        EXPECT_NEAR(mean, truth, 0.01) << name(kind) << " " << alpha << " " << cos_theta;
      }
}

TEST(LtcTargets, MagnitudeAndFresnelMatchQuadrature) {
  for (LtcTargetKind kind : kKinds)
    for (double alpha : {0.25, 1.0})
      for (double cos_theta : {1.0, 0.5, 0.15}) {
        const LtcTarget t(kind, alpha, cos_theta);
        const LobeMoments m = lobe_moments(t, 64);
        const double magnitude = lobe_integral(t, one);
        EXPECT_NEAR(m.magnitude, magnitude, 5e-3 * magnitude) << name(kind) << " " << alpha << " " << cos_theta;
        if (kind == LtcTargetKind::Ggx) {  // (the ndf table stores no Fresnel term)
          EXPECT_NEAR(m.fresnel, lobe_integral(t, schlick), 2e-3 * magnitude) << alpha << " " << cos_theta;
        }
        if (kind == LtcTargetKind::Ggx) {
          EXPECT_LE(magnitude, 1.0) << "no energy is made";
        } else {
          EXPECT_LE(magnitude, ggx_total_ndf(alpha)) << "a part of all the normals";
        }
      }
}

TEST(LtcTargets, SchlicksFresnelIntegratesAsTheTableSaysTheShaderMust) {
  // int f cos (f0 + (1 - f0)(1 - v.h)^5) = f0 magnitude + (1 - f0) fresnel (ltc_tables.glsl).
  const LtcTarget t(LtcTargetKind::Ggx, 0.4, 0.35);
  const LobeMoments m = lobe_moments(t, 64);
  for (double f0 : {0.04, 0.5, 1.0}) {
    const double truth = test::integrate_hemisphere(
        [&](const glm::dvec3& l) {
          const double vh = glm::dot(t.view(), glm::normalize(t.view() + l));
          return t.evaluate(l).value * (f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0));
        },
        1500);
    EXPECT_NEAR(f0 * m.magnitude + (1.0 - f0) * m.fresnel, truth, 2e-3 * truth) << f0;
  }
}

LtcFitSettings test_settings() { return ltc_table_fit_settings(); }

TEST(LtcFit, TheFittedLobeIntegratesToTheMagnitude) {
  for (LtcTargetKind kind : kKinds) {
    const LtcTarget t(kind, 0.5, 0.7);
    const LtcCell cell = fit_ltc_cell(t, test_settings());
    const Ltc ltc = cell.ltc();
    const double mass = test::integrate_sphere([&](const glm::dvec3& w) { return ltc.density(w); }, 1000);
    EXPECT_NEAR(cell.moments.magnitude * mass, cell.moments.magnitude, 1e-3 * cell.moments.magnitude) << name(kind);
  }
}

TEST(LtcFit, IsIsotropicAtNormalIncidence) {
  for (LtcTargetKind kind : kKinds)
    for (double alpha : {0.01, 0.3, 1.0}) {
      const LtcCell cell = fit_ltc_cell(LtcTarget(kind, alpha, 1.0), test_settings());
      const glm::vec4 t = pack_ltc_inverse(glm::inverse(cell.matrix));
      EXPECT_NEAR(t.x, 1.0f, 1e-6f) << "m00 = m11";
      EXPECT_EQ(t.y, 0.0f);
      EXPECT_EQ(t.z, 0.0f);
      EXPECT_GT(t.w, 0.0f);
    }
}

TEST(LtcFit, TheFitErrorEstimateMatchesQuadrature) {
  // The sampled fit error (ltc_fit_error) against the same L1 distance by quadrature.
  for (LtcTargetKind kind : kKinds) {
    const LtcTarget t(kind, 0.45, 0.5);
    const LtcCell cell = fit_ltc_cell(t, test_settings());
    const Ltc ltc = cell.ltc();
    const double m = cell.moments.magnitude;
    const double quadrature =
        test::integrate_hemisphere([&](const glm::dvec3& l) { return std::abs(t.evaluate(l).value - m * ltc.density(l)); },
                                   1500) / m;
    EXPECT_NEAR(ltc_fit_error(t, ltc, m, 128), quadrature, 0.01 * quadrature + 1e-3) << name(kind);
  }
}

TEST(LtcFit, FitsBetterThanItsStartAndWellWhereLtcsCan) {
  // Thresholds: what the paper's LTCs reach away from grazing views (docs/methods.md has the grid).
  struct Case {
    LtcTargetKind kind;
    double alpha, cos_theta, below;
  };
  for (const Case& c : {Case{LtcTargetKind::Ggx, 0.01, 1.0, 0.005}, Case{LtcTargetKind::Ggx, 0.1, 0.9, 0.03},
                        Case{LtcTargetKind::Ggx, 0.3, 0.8, 0.12}, Case{LtcTargetKind::Ggx, 0.6, 0.5, 0.22},
                        Case{LtcTargetKind::Ndf, 0.01, 1.0, 0.005}, Case{LtcTargetKind::Ndf, 0.1, 0.9, 0.05},
                        Case{LtcTargetKind::Ndf, 0.3, 0.8, 0.15}}) {
    const LtcTarget t(c.kind, c.alpha, c.cos_theta);
    const LtcCell cell = fit_ltc_cell(t, test_settings());
    const double fitted = ltc_fit_error(t, cell.ltc(), cell.moments.magnitude, 96);
    const Ltc start(ltc_matrix({0.0, 0.0, 0.0}, cell.moments.average_direction));  // a cosine about the lobe's axis
    EXPECT_LT(fitted, c.below) << name(c.kind) << " alpha " << c.alpha << " cos " << c.cos_theta;
    EXPECT_LT(fitted, 0.75 * ltc_fit_error(t, start, cell.moments.magnitude, 96)) << name(c.kind) << " alpha " << c.alpha;
  }
}

TEST(LtcFit, ASmallGridIsTheSameOnAnyNumberOfThreadsAndReportsEachCell) {
  LtcFitSettings s = test_settings();
  s.size = 5;
  int calls = 0, last = 0, total = 0;
  const LtcFit one_thread = fit_ltc_grid(LtcTargetKind::Ggx, s, {}, 1);
  const LtcFit two_threads = fit_ltc_grid(LtcTargetKind::Ggx, s, [&](int done, int t) {
    ++calls;
    EXPECT_GT(done, last);
    last = done;
    total = t;
  }, 2);
  EXPECT_EQ(last, 25);
  EXPECT_EQ(total, 25);
  EXPECT_GE(calls, 2);
  for (std::size_t k = 0; k < one_thread.cells.size(); ++k) {
    EXPECT_EQ(one_thread.cells[k].matrix, two_threads.cells[k].matrix) << k;
    EXPECT_TRUE(std::isfinite(glm::determinant(one_thread.cells[k].matrix))) << k;
  }
  // The grid's coordinates: the contract of ltc_table.hpp.
  EXPECT_EQ(ltc_grid_alpha(0, s), s.alpha_min);
  EXPECT_DOUBLE_EQ(ltc_grid_alpha(2, s), 0.25);
  EXPECT_EQ(ltc_grid_cos_theta(0, s), 1.0);
  EXPECT_DOUBLE_EQ(ltc_grid_cos_theta(2, s), 0.75);
  EXPECT_EQ(ltc_grid_cos_theta(4, s), s.cos_theta_min);
}

}  // namespace
}  // namespace glintlab
