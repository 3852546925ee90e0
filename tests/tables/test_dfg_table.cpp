// The dfg table's generator (src/tables/dfg/dfg.hpp): the split-sum's directional albedo
// f0 A + B of brdf.glsl's specular BRDF, against its limits and against an independent
// integration over a grid of incident directions written here from the textbook formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "core/math.hpp"
#include "tables/dfg/dfg.hpp"

using namespace glintlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Walter et al. 2007: D (eqs. 25 and 33) and Smith's Lambda in the tan(theta) form (GGX, Heitz
// 2014 eq. 72; Beckmann by Walter's rational fit in a = 1 / (alpha tan)).
double ndf(DfgNdf kind, double cos_h, double alpha) {
  const double c2 = cos_h * cos_h, tan2 = (1 - c2) / c2, a2 = alpha * alpha;
  if (kind == DfgNdf::Beckmann) return std::exp(-tan2 / a2) / (kPi * a2 * c2 * c2);
  return a2 / (kPi * c2 * c2 * (a2 + tan2) * (a2 + tan2));
}

double smith_lambda(DfgNdf kind, double cos_w, double alpha) {
  const double tan_w = std::sqrt(1 - cos_w * cos_w) / cos_w;
  if (kind == DfgNdf::Beckmann) {
    const double a = 1 / (alpha * tan_w);
    return a >= 1.6 ? 0.0 : (1 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
  }
  return 0.5 * (std::sqrt(1 + alpha * alpha * tan_w * tan_w) - 1);
}

/// A and B as midpoint sums over l in (cos theta_i, phi_i): f cos_i = D G2 / (4 cos_o) with
/// G2 = 1 / (1 + Lambda_o + Lambda_i), split by Schlick's (1 - o.h)^5.
DfgTerms hemisphere_grid(DfgNdf kind, double cos_o, double alpha) {
  constexpr int kMu = 1600, kPhi = 800;  // phi over half the circle: the integrand is even in phi
  const glm::dvec3 o(std::sqrt(1 - cos_o * cos_o), 0, cos_o);
  const double lambda_o = smith_lambda(kind, cos_o, alpha);
  DfgTerms sum;
  for (int j = 0; j < kMu; ++j) {
    const double mu = (j + 0.5) / kMu, s = std::sqrt(1 - mu * mu);
    const double lambda_i = smith_lambda(kind, mu, alpha);
    for (int k = 0; k < kPhi; ++k) {
      const double phi = kPi * (k + 0.5) / kPhi;
      const glm::dvec3 l(s * std::cos(phi), s * std::sin(phi), mu);
      const glm::dvec3 h = glm::normalize(o + l);
      const double value = ndf(kind, h.z, alpha) / (1 + lambda_o + lambda_i) / (4 * cos_o);
      const double fresnel = std::pow(1 - glm::dot(o, h), 5);
      sum.a += value * (1 - fresnel);
      sum.b += value * fresnel;
    }
  }
  const double cell = (1.0 / kMu) * (2 * kPi / (2 * kPhi)) * 2;  // d omega = dmu dphi, both halves
  return {sum.a * cell, sum.b * cell};
}

}  // namespace

TEST(DfgTable, MatchesAnIndependentHemisphereIntegration) {
  for (DfgNdf kind : {DfgNdf::Ggx, DfgNdf::Beckmann})
    for (double cos_o : {0.3, 0.75, 1.0})
      for (double alpha : {0.3, 0.6, 1.0}) {
        const DfgTerms table = dfg_terms(kind, cos_o, alpha), grid = hemisphere_grid(kind, cos_o, alpha);
        const char* name = kind == DfgNdf::Ggx ? "ggx" : "beckmann";
        EXPECT_NEAR(table.a, grid.a, 2e-4) << name << " cos_o " << cos_o << " alpha " << alpha;
        EXPECT_NEAR(table.b, grid.b, 2e-4) << name << " cos_o " << cos_o << " alpha " << alpha;
      }
}

TEST(DfgTable, MatchesPublishedSingleScatteringAlbedos) {
  // E_ss = A + B of GGX with height-correlated Smith, F = 1, at (cos_o, r), alpha = r^2: values to
  // four decimals measured by GGX and by uniform sampling (shared/notes/offline-and-newest.md, 1.4).
  struct Point {
    double cos_o, r, albedo;
  };
  for (const Point& p : {Point{1.0, 1.0, 0.3068}, Point{0.5, 1.0, 0.4507}, Point{0.1, 1.0, 0.7602},
                         Point{0.5, 0.5, 0.8573}, Point{1.0, 0.25, 0.9957}, Point{0.1, 0.25, 0.8968},
                         Point{0.5, 0.75, 0.6632}, Point{0.1, 0.1, 0.9942}}) {
    const DfgTerms t = dfg_terms(DfgNdf::Ggx, p.cos_o, p.r * p.r);
    EXPECT_NEAR(t.a + t.b, p.albedo, 1.5e-4) << "cos_o " << p.cos_o << " r " << p.r;
  }
}

TEST(DfgTable, AlbedoTendsToOneAsTheSurfaceBecomesAMirror) {
  for (DfgNdf kind : {DfgNdf::Ggx, DfgNdf::Beckmann})
    for (double cos_o : {0.02, 0.1, 0.4, 0.8, 1.0}) {
      const DfgTerms t = dfg_terms(kind, cos_o, kDfgAlphaMin);
      EXPECT_NEAR(t.a + t.b, 1.0, 1e-3) << "cos_o " << cos_o;
      // A mirror's Fresnel is Schlick's at o.h = cos_o: B = (1 - cos_o)^5.
      EXPECT_NEAR(t.b, std::pow(1 - cos_o, 5), 1e-3) << "cos_o " << cos_o;
    }
}

TEST(DfgTable, TheTableIsNonNegativeAndAnAlbedo) {
  const std::vector<float> values = generate_dfg_table();
  ASSERT_EQ(values.size(), dfg_table_value_count());
  for (int j = 0; j < kDfgTableSize; ++j)
    for (int i = 0; i < kDfgTableSize; ++i)
      for (int ndf = 0; ndf < 2; ++ndf) {
        const float a = values[dfg_texel(i, j) + 2 * ndf], b = values[dfg_texel(i, j) + 2 * ndf + 1];
        ASSERT_GE(a, 0.0f) << i << ", " << j;
        ASSERT_GE(b, 0.0f) << i << ", " << j;
        ASSERT_LE(a + b, 1.0f + 1e-4f) << i << ", " << j;
        if (j == 0) {
          EXPECT_GT(a + b, 0.999f) << "the smoothest row, cos_o " << dfg_cos_o(i);
        }
      }
  // The texel centres: cos_o and r = sqrt(alpha) at (k + 0.5) / size.
  EXPECT_DOUBLE_EQ(dfg_cos_o(0), 0.5 / kDfgTableSize);
  EXPECT_DOUBLE_EQ(dfg_alpha(kDfgTableSize - 1), std::pow(1 - 0.5 / kDfgTableSize, 2));
  // Texel (i, j) holds dfg_terms at its centre.
  const DfgTerms t = dfg_terms(DfgNdf::Beckmann, dfg_cos_o(7), dfg_alpha(19));
  EXPECT_FLOAT_EQ(values[dfg_texel(7, 19) + 2], static_cast<float>(t.a));
  EXPECT_FLOAT_EQ(values[dfg_texel(7, 19) + 3], static_cast<float>(t.b));
}
