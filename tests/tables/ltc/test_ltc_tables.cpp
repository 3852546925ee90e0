// The ltc-ggx and ltc-ndf tables as the framework builds them (src/tables/ltc/ltc_table.hpp's layout,
// src/tables/ltc_*_table.cpp): every cell finite and in range, magnitudes against
// quadrature, the fit error over the grid, the sphere ratio's limits, a quad lit through the table
// against the target integrated over it, and the GLSL lookups of shaders/ltc/ltc_tables.glsl
// against the C++ values (layer-0 layout, uv mapping, Schlick split, sphere form factor).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "gl_fixture.hpp"
#include "tables/ltc/ltc_sphere.hpp"
#include "tables/ltc/ltc_table.hpp"
#include "ltc_quadrature.hpp"
#include "tables/gpu_tables.hpp"

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLast = kLtcTableSize - 1;

/// The registered table's values, from the test cache (generated there once per build tree).
const std::vector<float>& values(const std::string& id) {
  static std::map<std::string, std::vector<float>> tables;
  auto it = tables.find(id);
  if (it == tables.end())
    it = tables.emplace(id, test::test_table_cache().load_or_generate(find_table(id).source).values).first;
  return it->second;
}

glm::vec4 texel(const std::string& id, int layer, int i, int j) {
  const auto& v = values(id);
  const std::size_t k = ltc_texel(layer, i, j);
  return {v[k], v[k + 1], v[k + 2], v[k + 3]};
}

LtcTargetKind kind_of(const std::string& id) { return id == "ltc-ggx" ? LtcTargetKind::Ggx : LtcTargetKind::Ndf; }
LtcTarget target_of(const std::string& id, int i, int j) {
  return LtcTarget(kind_of(id), ltc_grid_alpha(i, ltc_table_fit_settings()), ltc_grid_cos_theta(j, ltc_table_fit_settings()));
}
/// The LTC a cell of the table stores (what a shader rebuilds).
Ltc stored_ltc(const std::string& id, int i, int j) { return Ltc::from_inverse(unpack_ltc_inverse(texel(id, 0, i, j))); }

const std::string kIds[] = {"ltc-ggx", "ltc-ndf"};

TEST(LtcTables, EveryCellIsFiniteAndInRange) {
  for (const auto& id : kIds) {
    ASSERT_EQ(values(id).size(), ltc_table_value_count()) << id;
    for (float v : values(id)) ASSERT_TRUE(std::isfinite(v)) << id;
    for (int j = 0; j < kLtcTableSize; ++j)
      for (int i = 0; i < kLtcTableSize; ++i) {
        const glm::vec4 m = texel(id, 0, i, j), t = texel(id, 1, i, j);
        EXPECT_GT(glm::determinant(unpack_ltc_inverse(m)), 0.0) << id << " " << i << " " << j;
        EXPECT_GT(t.x, 0.0f) << id << " " << i << " " << j;
        const double alpha = ltc_grid_alpha(i, ltc_table_fit_settings());
        if (id == "ltc-ggx") {
          EXPECT_LE(t.x, 1.0f) << "the GGX lobe with G2 reflects at most all of the light: " << i << " " << j;
          EXPECT_GE(t.y, 0.0f);
          EXPECT_LE(t.y, t.x);
          EXPECT_GE(t.z, 0.0f);
          EXPECT_LE(t.z, 1.0f);
        } else {
          EXPECT_NEAR(t.y, ggx_total_ndf(alpha), 1e-6 * t.y) << "the closed form of the total NDF";
          EXPECT_LE(t.x, t.y * 1.01f) << "a part of all the normals: " << i << " " << j;
        }
      }
  }
}

TEST(LtcTables, TheStoredMagnitudesMatchQuadrature) {
  for (const auto& id : kIds)
    for (auto [i, j] : {std::pair{63, 0}, std::pair{40, 20}, std::pair{20, 45}, std::pair{50, 60}}) {
      const LtcTarget t = target_of(id, i, j);
      const double magnitude = test::integrate_hemisphere([&](const glm::dvec3& l) { return t.evaluate(l).value; }, 1500);
      EXPECT_NEAR(texel(id, 1, i, j).x, magnitude, 5e-3 * magnitude) << id << " " << i << " " << j;
    }
}

TEST(LtcTables, TheFitErrorOverTheGridIsSmallAwayFromGrazingViews) {
  // The L1 distance of the stored lobe from its target, relative to the magnitude, on every
  // third cell (the whole grid: benchmarks/ltc_fit_report). Thresholds from docs/methods.md's table.
  for (const auto& id : kIds) {
    double worst = 0.0, worst_within_60 = 0.0, worst_smooth_normal = 0.0;
    for (int j = 0; j < kLtcTableSize; j += 3)
      for (int i = 0; i < kLtcTableSize; i += 3) {
        const LtcTarget t = target_of(id, i, j);
        const double e = ltc_fit_error(t, stored_ltc(id, i, j), texel(id, 1, i, j).x, 40);
        worst = std::max(worst, e);
        if (t.view().z >= 0.5) worst_within_60 = std::max(worst_within_60, e);
        if (j == 0 && i <= 32) worst_smooth_normal = std::max(worst_smooth_normal, e);
      }
    const bool ggx = id == "ltc-ggx";
    EXPECT_LT(worst_smooth_normal, ggx ? 0.045 : 0.11) << id << ": alpha <= 0.26 at normal incidence";
    EXPECT_LT(worst_within_60, ggx ? 0.25 : 0.35) << id << ": theta_v <= 60 degrees";
    // The L1 distance of two lobes of the same mass is at most 2: the grazing views come close.
    EXPECT_LT(worst, ggx ? 0.8 : 1.2) << id << ": anywhere, grazing views included";
  }
}

TEST(LtcTables, TheSphereRatioIsZAboveTheHorizonAndZeroBelow) {
  for (int j = 0; j < kLtcTableSize; ++j)
    for (int i = 0; i < kLtcTableSize; ++i) {
      const double z = 2.0 * i / kLast - 1.0, f = static_cast<double>(j) / kLast;
      const double sigma = std::asin(std::sqrt(f)), omega = std::acos(z);
      const float s = texel("ltc-ggx", 1, i, j).z;
      if (omega + sigma <= 0.5 * kPi) {
        EXPECT_NEAR(s, z, 1e-6) << i << " " << j;
      }
      if (omega - sigma >= 0.5 * kPi) {
        EXPECT_NEAR(s, 0.0, 1e-6) << i << " " << j;
      }
      EXPECT_NEAR(s, clipped_cap_ratio(z, f), 1e-6) << i << " " << j;
    }
}

TEST(LtcTables, AQuadLitThroughTheTableMatchesTheTargetIntegratedOverIt) {
  // The whole chain a shader runs: the stored M^-1, the polygon integral, the magnitude, against
  // the lobe integrated over the quad's directions; within the cell's fit error.
  const glm::dvec3 c(0.3, 0.2, 1.2), e1(0.5, 0.0, 0.0), e2(0.0, 0.4, 0.1);
  const std::array<glm::dvec3, 4> q = {c - e1 - e2, c + e1 - e2, c + e1 + e2, c - e1 + e2};
  const glm::dvec3 normal = glm::cross(q[1] - q[0], q[3] - q[0]);
  for (const auto& id : kIds)
    for (auto [i, j] : {std::pair{40, 10}, std::pair{25, 30}, std::pair{55, 40}}) {
      const LtcTarget t = target_of(id, i, j);
      constexpr int kN = 600;
      double truth = 0.0;
      for (int a = 0; a < kN; ++a)
        for (int b = 0; b < kN; ++b) {
          const glm::dvec3 p = q[0] + (q[1] - q[0]) * ((a + 0.5) / kN) + (q[3] - q[0]) * ((b + 0.5) / kN);
          const double r2 = glm::dot(p, p);
          truth += t.evaluate(p / std::sqrt(r2)).value * std::abs(glm::dot(p, normal)) / (r2 * std::sqrt(r2));
        }
      truth /= static_cast<double>(kN) * kN;
      const float magnitude = texel(id, 1, i, j).x;
      const double ltc = magnitude * std::abs(ltc_polygon_integral(stored_ltc(id, i, j), q));
      const double error = ltc_fit_error(t, stored_ltc(id, i, j), magnitude, 64);
      EXPECT_NEAR(ltc, truth, error * magnitude + 1e-3 * truth) << id << " " << i << " " << j;
    }
}

/// Both tables resident and bound for evaluate_glsl.
void bind_ltc_tables() {
  test::context();
  static GpuTables tables(test::test_table_cache());
  tables.require(std::vector<std::string>{"ltc-ggx", "ltc-ndf"});
  tables.bind();
}

TEST(LtcTables, TheGlslLookupsReturnTheCellsAtTheirCentres) {
  bind_ltc_tables();
  std::vector<glm::vec4> a, b;
  for (int j = 0; j < kLtcTableSize; j += 7)
    for (int i = 0; i < kLtcTableSize; i += 9) {
      const double r = static_cast<double>(i) / kLast, x = static_cast<double>(j) / kLast;
      a.emplace_back(static_cast<float>(r * r), static_cast<float>(1.0 - x * x), i, j);
      b.emplace_back(0.3f, -0.5f, 0.8f, 0.0f);
    }
  for (const auto& id : kIds) {
    const std::string sampler = id == "ltc-ggx" ? "uLtcGgx" : "uLtcNdf";
    const auto matrix = test::evaluate_glsl("#include \"ltc/ltc_tables.glsl\"",
                                            "vec4 evaluate(vec4 a, vec4 b) { return vec4(ltcInverseMatrix(" + sampler +
                                                ", a.x, a.y) * b.xyz, LTC_TABLE_SIZE); }",
                                            a, b);
    const auto terms = test::evaluate_glsl("#include \"ltc/ltc_tables.glsl\"",
                                           "vec4 evaluate(vec4 a, vec4 b) { return ltcTerms(" + sampler + ", a.x, a.y); }", a, b);
    for (std::size_t k = 0; k < a.size(); ++k) {
      const int i = static_cast<int>(a[k].z), j = static_cast<int>(a[k].w);
      // C++: M^-1 of the fit, normalised by m11, applied to b.
      const glm::dmat3 m_inv = glm::inverse(stored_ltc(id, i, j).matrix());
      const glm::dvec3 expected = m_inv * glm::dvec3(b[k]) / m_inv[1][1];
      const double scale = glm::length(expected) + 1.0;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(matrix[k][c], expected[c], 1e-3 * scale) << id << " cell " << i << " " << j << " row " << c;
      EXPECT_EQ(matrix[k].w, static_cast<float>(kLtcTableSize)) << "LTC_TABLE_SIZE is kLtcTableSize";
      const glm::vec4 t = texel(id, 1, i, j);
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(terms[k][c], t[c], 1e-3 * std::abs(t[c]) + 1e-6) << id << " " << i << " " << j;
    }
  }
}

TEST(LtcTables, TheGlslSphereFormFactorIsTheClippedCap) {
  bind_ltc_tables();
  std::vector<glm::vec4> a, b;
  for (double z : {-0.95, -0.4, -0.05, 0.0, 0.2, 0.6, 1.0})
    for (double f : {0.0, 0.01, 0.1, 0.37, 0.8, 1.0}) {
      const double s = std::sqrt(1.0 - z * z);
      a.emplace_back(static_cast<float>(f * s), 0.0f, static_cast<float>(f * z), 0.0f);
      b.emplace_back(static_cast<float>(z), static_cast<float>(f), 0.0f, 0.0f);
    }
  const auto r = test::evaluate_glsl("#include \"ltc/ltc_tables.glsl\"",
                                     "vec4 evaluate(vec4 a, vec4 b) { return vec4(ltcSphereFormFactor(a.xyz), "
                                     "ltcSpecularScale(vec4(0.8, 0.1, 0.0, 0.0), vec3(0.0, 0.5, 1.0))); }",
                                     a, b);
  for (std::size_t k = 0; k < a.size(); ++k) {
    // Between cell centres the table is interpolated linearly: within ~1e-3 of the exact cap.
    EXPECT_NEAR(r[k].x, clipped_cap_form_factor(b[k].x, b[k].y), 2e-3) << "z " << b[k].x << " |F| " << b[k].y;
    EXPECT_NEAR(r[k].y, 0.1f, 1e-6f);
    EXPECT_NEAR(r[k].z, 0.45f, 1e-6f);
    EXPECT_NEAR(r[k].w, 0.8f, 1e-6f);
  }
}

}  // namespace
}  // namespace glintlab
