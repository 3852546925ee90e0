// The CP decomposition of NDF blocks (src/prefilter/cp_decomposition.hpp): recovery of tensors of
// known rank, monotone ALS, the range queries against brute-force sums and integrals of the
// reconstruction, nonnegativity, over-factoring, determinism and the degenerate inputs.
// The truth is never the code under test: synthetic tensors built from known factors, residuals
// and integrals summed here in double from value().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "core/error.hpp"
#include "prefilter/cp_decomposition.hpp"

namespace glintlab {
namespace {

// sum_r a(i,r) b(j,r) c(k,r) with factors drawn uniform in [0, 1) and cubed: nonnegative, and
// spread enough that the components are identifiable (uniform factors are nearly collinear).
Tensor3 known_rank_tensor(int I, int J, int K, int rank, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto factor = [&](int n) {
    Eigen::MatrixXd f(n, rank);
    for (int r = 0; r < rank; ++r)
      for (int x = 0; x < n; ++x) f(x, r) = std::pow(u(rng), 3.0);
    return f;
  };
  const Eigen::MatrixXd a = factor(I), b = factor(J), c = factor(K);
  Tensor3 x(I, J, K);
  for (int i = 0; i < I; ++i)
    for (int j = 0; j < J; ++j)
      for (int k = 0; k < K; ++k) x.at(i, j, k) = static_cast<float>(a.row(i).cwiseProduct(b.row(j)).dot(c.row(k)));
  return x;
}

// Nonnegative data of full rank: about half the entries zero, the rest uniform.
Tensor3 random_nonnegative_tensor(int I, int J, int K, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Tensor3 x(I, J, K);
  for (float& v : x.values) v = std::max(0.0f, 2.0f * u(rng) - 1.0f);
  return x;
}

// ||X - X^|| / ||X|| from value(), in double.
double brute_force_relative_error(const Tensor3& x, const CpFactors& f) {
  double residual = 0.0, norm = 0.0;
  for (int i = 0; i < x.I; ++i)
    for (int j = 0; j < x.J; ++j)
      for (int k = 0; k < x.K; ++k) {
        const double d = double(x.at(i, j, k)) - double(f.value(i, j, k));
        residual += d * d;
        norm += double(x.at(i, j, k)) * x.at(i, j, k);
      }
  return std::sqrt(residual / norm);
}

// The length of [t0, t1] inside texel [x, x + 1).
double overlap(double t0, double t1, int x) { return std::max(0.0, std::min(t1, x + 1.0) - std::max(t0, double(x))); }

// The integral of the piecewise-constant reconstruction of slice k over [i0, i1] x [j0, j1].
double brute_force_integral(const CpFactors& f, double i0, double i1, double j0, double j1, int k) {
  double sum = 0.0;
  for (int i = 0; i < f.a.rows(); ++i)
    for (int j = 0; j < f.b.rows(); ++j) sum += overlap(i0, i1, i) * overlap(j0, j1, j) * f.value(i, j, k);
  return sum;
}

bool bitwise_equal(const Eigen::MatrixXf& p, const Eigen::MatrixXf& q) {
  return p.rows() == q.rows() && p.cols() == q.cols() &&
         std::memcmp(p.data(), q.data(), sizeof(float) * static_cast<std::size_t>(p.size())) == 0;
}

bool all_finite(const CpFactors& f) { return f.a.allFinite() && f.b.allFinite() && f.c.allFinite(); }

class KnownRank : public testing::TestWithParam<int> {};

TEST_P(KnownRank, NonnegativeHalsRecoversItFromARandomStart) {
  const int rank = GetParam();
  const Tensor3 x = known_rank_tensor(10, 9, 40, rank, 7u + rank);
  CpSettings s;
  s.rank = rank;
  s.tolerance = 1e-10;
  s.max_iterations = 3000;
  const CpFactors f = decompose(x, s);
  EXPECT_LT(f.relative_error, 1e-3) << "after " << f.iterations << " sweeps";
  EXPECT_NEAR(brute_force_relative_error(x, f), f.relative_error, 1e-6) << "the reported error is the explicit one";
  EXPECT_GE(f.a.minCoeff(), 0.0f);
  EXPECT_GE(f.b.minCoeff(), 0.0f);
  EXPECT_GE(f.c.minCoeff(), 0.0f);
}

TEST_P(KnownRank, PlainAlsRecoversItFromARandomStart) {
  const int rank = GetParam();
  const Tensor3 x = known_rank_tensor(10, 9, 40, rank, 7u + rank);
  CpSettings s;
  s.rank = rank;
  s.nonnegative = false;
  s.tolerance = 1e-12;
  s.max_iterations = 3000;
  const CpFactors f = decompose(x, s);
  EXPECT_LT(f.relative_error, 1e-5) << "after " << f.iterations << " sweeps";
  EXPECT_NEAR(brute_force_relative_error(x, f), f.relative_error, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(CpDecomposition, KnownRank, testing::Values(4, 8));

TEST(CpDecomposition, NvecsStartAlsoRecoversAKnownRank) {
  const Tensor3 x = known_rank_tensor(10, 9, 40, 4, 3u);
  CpSettings s;
  s.rank = 4;
  s.init = CpInit::nvecs;
  s.tolerance = 1e-10;
  s.max_iterations = 3000;
  EXPECT_LT(decompose(x, s).relative_error, 1e-3);
  s.nonnegative = false;
  s.tolerance = 1e-12;
  EXPECT_LT(decompose(x, s).relative_error, 1e-5);
}

TEST(CpDecomposition, PlainAlsErrorNeverIncreasesOverSweeps) {
  // Each ALS step solves its least-squares subproblem exactly, so the fit can only improve
  // (Kolda & Bader section 3.4); data of full rank keep the fit away from 0 for many sweeps.
  const Tensor3 x = random_nonnegative_tensor(8, 7, 30, 11u);
  for (CpInit init : {CpInit::random, CpInit::nvecs}) {
    CpSettings s;
    s.rank = 5;
    s.nonnegative = false;
    s.init = init;
    s.tolerance = 1e-9;
    s.max_iterations = 300;
    const CpFactors f = decompose(x, s);
    ASSERT_EQ(f.error_history.size(), static_cast<std::size_t>(f.iterations));
    ASSERT_GT(f.iterations, 10);
    for (std::size_t n = 1; n < f.error_history.size(); ++n)
      EXPECT_LE(f.error_history[n], f.error_history[n - 1] + 1e-12) << "sweep " << n;
    EXPECT_NEAR(f.error_history.back(), f.relative_error, 1e-5) << "the Gram identity agrees with the explicit error";
  }
}

TEST(CpDecomposition, HalsErrorNeverIncreasesOverSweeps) {
  // Each HALS column update is the exact nonnegative least-squares solution for that column.
  const Tensor3 x = random_nonnegative_tensor(8, 7, 30, 12u);
  CpSettings s;
  s.rank = 5;
  s.tolerance = 1e-9;
  s.max_iterations = 300;
  const CpFactors f = decompose(x, s);
  ASSERT_GT(f.iterations, 10);
  for (std::size_t n = 1; n < f.error_history.size(); ++n)
    EXPECT_LE(f.error_history[n], f.error_history[n - 1] + 1e-12) << "sweep " << n;
}

TEST(CpDecomposition, RangeSumsOverWholeTexelsAreSumsOfValues) {
  const Tensor3 x = random_nonnegative_tensor(9, 8, 12, 21u);
  for (bool nonnegative : {true, false}) {
    CpSettings s;
    s.rank = 6;
    s.nonnegative = nonnegative;
    s.max_iterations = 50;
    const CpFactors f = decompose(x, s);
    const CpRangeQuery query(f);
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
      int i0 = int(rng() % 10), i1 = int(rng() % 10), j0 = int(rng() % 9), j1 = int(rng() % 9);
      if (i0 > i1) std::swap(i0, i1);
      if (j0 > j1) std::swap(j0, j1);
      const int k = int(rng() % 12);
      double sum = 0.0, magnitude = 0.0;
      for (int i = i0; i < i1; ++i)
        for (int j = j0; j < j1; ++j) {
          sum += f.value(i, j, k);
          magnitude += std::abs(f.value(i, j, k));
        }
      EXPECT_NEAR(query.range_sum(float(i0), float(i1), float(j0), float(j1), k), sum, 1e-5 * (1.0 + magnitude))
          << "[" << i0 << ", " << i1 << "] x [" << j0 << ", " << j1 << "] slice " << k;
    }
  }
}

TEST(CpDecomposition, RangeSumsOverFractionalBoxesAreIntegralsOfTheReconstruction) {
  const Tensor3 x = random_nonnegative_tensor(9, 8, 12, 22u);
  for (bool nonnegative : {true, false}) {
    CpSettings s;
    s.rank = 6;
    s.nonnegative = nonnegative;
    s.max_iterations = 50;
    const CpFactors f = decompose(x, s);
    const CpRangeQuery query(f);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> ui(0.0f, 9.0f), uj(0.0f, 8.0f);
    for (int trial = 0; trial < 200; ++trial) {
      float i0 = ui(rng), i1 = ui(rng), j0 = uj(rng), j1 = uj(rng);
      if (trial % 10 == 0) i1 = 9.0f, j0 = 0.0f;  // the block's edges are valid bounds
      if (i0 > i1) std::swap(i0, i1);
      if (j0 > j1) std::swap(j0, j1);
      const int k = int(rng() % 12);
      const double truth = brute_force_integral(f, i0, i1, j0, j1, k);
      const double magnitude = brute_force_integral(f, 0, 9, 0, 8, k);
      EXPECT_NEAR(query.range_sum(i0, i1, j0, j1, k), truth, 1e-5 * (1.0 + std::abs(magnitude)))
          << "[" << i0 << ", " << i1 << "] x [" << j0 << ", " << j1 << "] slice " << k;
    }
  }
}

TEST(CpDecomposition, NonnegativeModeNeverGivesANegativeValueOrRangeSum) {
  // Unconstrained ALS on the same data does go negative: the property comes from HALS.
  const Tensor3 x = random_nonnegative_tensor(10, 10, 24, 31u);
  CpSettings s;
  s.rank = 8;
  s.max_iterations = 200;
  CpSettings unconstrained = s;
  unconstrained.nonnegative = false;
  const CpFactors als = decompose(x, unconstrained);
  float lowest_als = 0.0f;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 24; ++k) lowest_als = std::min(lowest_als, als.value(i, j, k));
  ASSERT_LT(lowest_als, 0.0f) << "the data must be able to produce negative reconstructions";

  const CpFactors f = decompose(x, s);
  EXPECT_GE(f.a.minCoeff(), 0.0f);
  EXPECT_GE(f.b.minCoeff(), 0.0f);
  EXPECT_GE(f.c.minCoeff(), 0.0f);
  const CpRangeQuery query(f);
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0.0f, 10.0f);
  for (int k = 0; k < 24; ++k) {
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j) EXPECT_GE(f.value(i, j, k), 0.0f);
    for (int trial = 0; trial < 50; ++trial) {
      const float i0 = u(rng), j0 = u(rng);
      // Near-empty ranges ending just past a texel edge are where float rounding bites.
      const float i1 = trial % 2 ? std::nextafter(std::ceil(i0), 11.0f) : i0 + u(rng) * 0.01f;
      const float j1 = std::min(10.0f, j0 + u(rng) * 0.5f);
      EXPECT_GE(query.range_sum(i0, std::min(i1, 10.0f), j0, j1, k), 0.0f);
    }
  }
}

TEST(CpDecomposition, PrefixSumsOfNonnegativeFactorsNeverGiveANegativeRange) {
  // A range ending a few ulps past a texel edge can come out a rounding error below 0 (the
  // float prefix sum was rounded up); nonnegative factors clamp it. The unclamped sums of the
  // same columns show that the case occurs.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Eigen::MatrixXf m(16, 64);
  for (int r = 0; r < 64; ++r)
    for (int x = 0; x < 16; ++x) m(x, r) = std::pow(u(rng), 4.0f) * std::pow(10.0f, 3.0f * u(rng));
  const FactorPrefixSums clamped(m, true), unclamped(m, false);
  int negative_unclamped = 0;
  for (int r = 0; r < 64; ++r)
    for (int edge = 1; edge < 16; ++edge) {
      float t0 = float(edge), t1 = float(edge);
      for (int step = 0; step < 12; ++step) {
        t0 = std::nextafter(t0, 0.0f);
        t1 = std::nextafter(t1, 16.0f);
        EXPECT_GE(clamped.range_sum(t0, t1, r), 0.0f);
        negative_unclamped += unclamped.range_sum(t0, t1, r) < 0.0f;
      }
    }
  EXPECT_GT(negative_unclamped, 0);
}

TEST(CpDecomposition, RankAboveTheDataRankDoesNotDiverge) {
  // Rank 12 for data of rank 3 whose first mode has only 6 entries.
  const Tensor3 x = known_rank_tensor(6, 8, 20, 3, 41u);
  for (bool nonnegative : {true, false}) {
    CpSettings s;
    s.rank = 12;
    s.nonnegative = nonnegative;
    s.tolerance = 1e-9;
    s.max_iterations = 2000;
    const CpFactors f = decompose(x, s);
    EXPECT_TRUE(all_finite(f)) << "nonnegative " << nonnegative;
    EXPECT_LT(f.relative_error, 1e-3) << "nonnegative " << nonnegative << ", " << f.iterations << " sweeps";
    EXPECT_LT(f.c.cwiseAbs().maxCoeff(), 1e3f * x.values.size()) << "no diverging components";
  }
}

TEST(CpDecomposition, TheSameSeedGivesTheSameBits) {
  const Tensor3 x = random_nonnegative_tensor(8, 8, 20, 51u);
  for (bool nonnegative : {true, false}) {
    CpSettings s;
    s.rank = 6;
    s.nonnegative = nonnegative;
    s.restarts = 2;
    const CpFactors p = decompose(x, s), q = decompose(x, s);
    EXPECT_TRUE(bitwise_equal(p.a, q.a) && bitwise_equal(p.b, q.b) && bitwise_equal(p.c, q.c));
    EXPECT_EQ(p.error_history, q.error_history);
    s.seed = 2;
    const CpFactors other = decompose(x, s);
    EXPECT_FALSE(bitwise_equal(p.c, other.c)) << "the seed must reach the start";
  }
}

TEST(CpDecomposition, RestartsKeepTheBestFit) {
  const Tensor3 x = random_nonnegative_tensor(8, 8, 20, 61u);
  CpSettings s;
  s.rank = 4;
  const double single = decompose(x, s).relative_error;
  s.restarts = 4;
  const CpFactors best = decompose(x, s);
  EXPECT_LE(best.relative_error, single) << "restart 0 is the single run";
  EXPECT_NEAR(brute_force_relative_error(x, best), best.relative_error, 1e-6);
}

TEST(CpDecomposition, ComponentsComeSortedByWeightWithUnitAngularFactors) {
  const Tensor3 x = random_nonnegative_tensor(8, 8, 20, 71u);
  CpSettings s;
  s.rank = 6;
  const CpFactors f = decompose(x, s);
  for (int r = 0; r < 6; ++r) {
    EXPECT_NEAR(f.a.col(r).norm(), 1.0f, 1e-5f);
    EXPECT_NEAR(f.b.col(r).norm(), 1.0f, 1e-5f);
    if (r > 0) {
      EXPECT_GE(f.c.col(r - 1).norm(), f.c.col(r).norm());
    }
  }
}

TEST(CpDecomposition, EmptyAndZeroTensorsGiveZeroFactors) {
  for (const Tensor3& x : {Tensor3(0, 4, 5), Tensor3(4, 4, 0), Tensor3(3, 4, 5)}) {
    const CpFactors f = decompose(x, {});
    EXPECT_EQ(f.a.rows(), x.I);
    EXPECT_EQ(f.b.rows(), x.J);
    EXPECT_EQ(f.c.rows(), x.K);
    EXPECT_EQ(f.a.cols(), 16);
    EXPECT_EQ(f.relative_error, 0.0);
    EXPECT_EQ(f.iterations, 0);
    EXPECT_TRUE(f.a.isZero(0.0f) && f.b.isZero(0.0f) && f.c.isZero(0.0f));
  }
  const CpRangeQuery query(decompose(Tensor3(3, 4, 5), {}));
  EXPECT_EQ(query.range_sum(0.0f, 3.0f, 0.0f, 4.0f, 2), 0.0f);
}

TEST(CpDecomposition, FewerSlicesThanTheRankStillFit) {
  const Tensor3 x = known_rank_tensor(8, 8, 3, 2, 81u);
  for (bool nonnegative : {true, false}) {
    CpSettings s;
    s.rank = 8;
    s.nonnegative = nonnegative;
    const CpFactors f = decompose(x, s);
    EXPECT_TRUE(all_finite(f));
    EXPECT_LT(f.relative_error, 1e-3) << "nonnegative " << nonnegative;
  }
}

TEST(CpDecomposition, BadSettingsAndTensorsAreRejectedByName) {
  const Tensor3 x = random_nonnegative_tensor(4, 4, 4, 91u);
  auto message = [&](const Tensor3& t, const CpSettings& s) {
    try {
      (void)decompose(t, s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CpSettings s;
  s.rank = 0;
  EXPECT_NE(message(x, s).find("rank = 0"), std::string::npos) << message(x, s);
  s = {};
  s.tolerance = std::nan("");
  EXPECT_NE(message(x, s).find("tolerance"), std::string::npos) << message(x, s);
  s = {};
  s.restarts = 0;
  EXPECT_NE(message(x, s).find("restarts = 0"), std::string::npos) << message(x, s);
  Tensor3 wrong = x;
  wrong.values.pop_back();
  EXPECT_NE(message(wrong, {}).find("holds 63 values"), std::string::npos) << message(wrong, {});
  Tensor3 nan = x;
  nan.at(1, 2, 3) = std::nanf("");
  EXPECT_NE(message(nan, {}).find("finite"), std::string::npos) << message(nan, {});
}

}  // namespace
}  // namespace glintlab
