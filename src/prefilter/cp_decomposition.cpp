#include "prefilter/cp_decomposition.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>

#include "core/error.hpp"

namespace glintlab {
namespace {

using MatrixD = Eigen::MatrixXd;
using RowMatrixD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatrixFMap = Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

// Ridge added to the Gram matrix before the solve, relative to its mean diagonal: keeps the
// Cholesky factorisation defined when R exceeds a mode's size or components coincide
// (tensorly's l2_reg), far below anything the fit can see.
constexpr double kRidge = 1e-10;
// HALS keeps entries at or above this (times the data's rms for c, which carries the scale; a and
// b have unit columns) instead of 0, so that no
// column becomes exactly zero and stays there (Gillis & Glineur 2012).
constexpr double kHalsFloor = 1e-12;

// Fills m with uniform [0, 1) values from rng, column by column (specified exactly, unlike
// std::uniform_real_distribution, so the bits do not depend on the standard library).
void fill_uniform(MatrixD& m, std::mt19937& rng) {
  const double to_unit = 1.0 / 4294967296.0;
  for (Eigen::Index r = 0; r < m.cols(); ++r)
    for (Eigen::Index i = 0; i < m.rows(); ++i) m(i, r) = static_cast<double>(rng()) * to_unit;
}

// The tensor in double, seen as the (I J) x K matrix of its k-fibres.
struct Unfolded {
  int I, J, K;
  RowMatrixD ij_by_k;
  double norm_squared;
};

Unfolded unfold(const Tensor3& x) {
  Unfolded u{x.I, x.J, x.K, RowMatrixFMap(x.values.data(), Eigen::Index{x.I} * x.J, x.K).cast<double>(), 0.0};
  u.norm_squared = u.ij_by_k.squaredNorm();
  return u;
}

// Leading eigenvectors of X_(n) X_(n)^T for mode a (n = 0) or b (n = 1): Kolda & Bader's nvecs.
MatrixD leading_vectors(const Unfolded& x, int mode, int rank, bool nonnegative, std::mt19937& rng) {
  const int n = mode == 0 ? x.I : x.J;
  MatrixD gram = MatrixD::Zero(n, n);
  if (mode == 0) {
    // X_(1) is I x (J K) and contiguous in ij_by_k's storage.
    Eigen::Map<const RowMatrixD> x1(x.ij_by_k.data(), x.I, Eigen::Index{x.J} * x.K);
    gram = x1 * x1.transpose();
  } else {
    for (int i = 0; i < x.I; ++i) {
      const auto slab = x.ij_by_k.middleRows(Eigen::Index{i} * x.J, x.J);  // J x K
      gram.noalias() += slab * slab.transpose();
    }
  }
  MatrixD out(n, rank);
  fill_uniform(out, rng);  // columns past n stay random
  const Eigen::SelfAdjointEigenSolver<MatrixD> eig(gram);
  for (int r = 0; r < std::min(n, rank); ++r) {
    out.col(r) = eig.eigenvectors().col(n - 1 - r);  // eigenvalues ascend
    if (nonnegative) out.col(r) = out.col(r).cwiseAbs();
  }
  return out;
}

// One fit from one start. Factors a and b keep unit columns between updates; c carries the
// scale. The sweep updates c, then a, then b, so the start needs only a and b.
struct Fit {
  MatrixD a, b, c;
  std::vector<double> history;
  int iterations = 0;
};

class Fitter {
 public:
  Fitter(const Unfolded& x, const CpSettings& s) : x_(x), s_(s) {}

  Fit run(MatrixD a, MatrixD b) {
    const int R = s_.rank;
    Fit fit{std::move(a), std::move(b), MatrixD::Zero(x_.K, R), {}, 0};
    normalise_into_c(fit.a, fit.c, nullptr);
    normalise_into_c(fit.b, fit.c, nullptr);
    const double floor_c = kHalsFloor * std::sqrt(x_.norm_squared / (double(x_.I) * x_.J * x_.K));
    MatrixD kr(Eigen::Index{x_.I} * x_.J, R), t(Eigen::Index{x_.I} * x_.J, R), m;
    double previous = 0.0;
    for (int it = 1; it <= s_.max_iterations; ++it) {
      // Mode c: M = X_(3) (A khatri-rao B). The Khatri-Rao product of the two small angular
      // modes is (I J) x R, no bigger than one MTTKRP intermediate; the one with c never exists.
      for (int i = 0; i < x_.I; ++i)
        for (int j = 0; j < x_.J; ++j) kr.row(Eigen::Index{i} * x_.J + j) = fit.a.row(i).cwiseProduct(fit.b.row(j));
      m.noalias() = x_.ij_by_k.transpose() * kr;  // K x R
      update(fit.c, m, gram(fit.a).cwiseProduct(gram(fit.b)), floor_c);

      // Modes a and b share T = X_(ij),k C (I J x R): c does not change between them.
      t.noalias() = x_.ij_by_k * fit.c;
      m.setZero(x_.I, R);
      for (int i = 0; i < x_.I; ++i)
        for (int j = 0; j < x_.J; ++j) m.row(i) += t.row(Eigen::Index{i} * x_.J + j).cwiseProduct(fit.b.row(j));
      update(fit.a, m, gram(fit.b).cwiseProduct(gram(fit.c)), kHalsFloor);
      normalise_into_c(fit.a, fit.c, &t);  // T scales with c's columns

      m.setZero(x_.J, R);
      for (int i = 0; i < x_.I; ++i)
        for (int j = 0; j < x_.J; ++j) m.row(j) += t.row(Eigen::Index{i} * x_.J + j).cwiseProduct(fit.a.row(i));
      update(fit.b, m, gram(fit.a).cwiseProduct(gram(fit.c)), kHalsFloor);

      // Relative error from the Gram identity; <X, X^> = sum M_b o B with the B just solved.
      const double inner = m.cwiseProduct(fit.b).sum();
      const double model = (gram(fit.a).cwiseProduct(gram(fit.b)).cwiseProduct(gram(fit.c))).sum();
      const double error = std::sqrt(std::max(0.0, x_.norm_squared - 2.0 * inner + model) / x_.norm_squared);
      normalise_into_c(fit.b, fit.c, nullptr);
      fit.history.push_back(error);
      fit.iterations = it;
      if (it > 1 && std::abs(previous - error) < s_.tolerance) break;
      previous = error;
    }
    return fit;
  }

 private:
  static MatrixD gram(const MatrixD& f) { return f.transpose() * f; }

  // Solves for one factor given its MTTKRP m and the Hadamard product v of the other Grams.
  void update(MatrixD& f, const MatrixD& m, MatrixD v, double floor) const {
    const Eigen::Index R = v.rows();
    const double trace = v.trace();
    const double ridge = trace > 0.0 ? kRidge * trace / double(R) : 1e-300;
    if (!s_.nonnegative) {
      // Unconstrained least squares: F = M (V + ridge I)^-1 (Kolda & Bader eq. 3.6).
      v.diagonal().array() += ridge;
      const Eigen::LLT<MatrixD> llt(v);
      if (llt.info() == Eigen::Success)
        f = llt.solve(m.transpose()).transpose();
      else
        f = v.completeOrthogonalDecomposition().solve(m.transpose()).transpose();
      return;
    }
    // HALS: each column in turn is the exact nonnegative least-squares solution with the others
    // fixed, f_r <- max(floor, f_r + (M_r - F V_r) / V_rr) (Cichocki & Phan 2009, eq. 11).
    for (Eigen::Index r = 0; r < R; ++r) {
      const double vrr = v(r, r) + ridge;
      if (!(vrr > 0.0)) continue;
      f.col(r) = (f.col(r) + (m.col(r) - f * v.col(r)) / vrr).cwiseMax(floor);
    }
  }

  // Scales f's columns to unit length and c's (and t's) columns by the lengths, which leaves the
  // model unchanged. Zero columns stay.
  static void normalise_into_c(MatrixD& f, MatrixD& c, MatrixD* t) {
    for (Eigen::Index r = 0; r < f.cols(); ++r) {
      const double length = f.col(r).norm();
      if (!(length > 0.0)) continue;
      f.col(r) /= length;
      c.col(r) *= length;
      if (t) t->col(r) *= length;
    }
  }

  const Unfolded& x_;
  const CpSettings& s_;
};

// ||X - X^||^2 of float factors, in double.
double residual_squared(const Unfolded& x, const Eigen::MatrixXf& a, const Eigen::MatrixXf& b, const Eigen::MatrixXf& c) {
  const MatrixD ad = a.cast<double>(), bd = b.cast<double>(), cd = c.cast<double>();
  MatrixD kr(Eigen::Index{x.I} * x.J, a.cols());
  for (int i = 0; i < x.I; ++i)
    for (int j = 0; j < x.J; ++j) kr.row(Eigen::Index{i} * x.J + j) = ad.row(i).cwiseProduct(bd.row(j));
  return (x.ij_by_k - kr * cd.transpose()).squaredNorm();
}

// Signs (unconstrained ALS): the largest-magnitude entry of each a and b column positive, the
// sign pushed into c; then components sorted by the length of their c column, largest first.
void canonicalise(MatrixD& a, MatrixD& b, MatrixD& c) {
  for (Eigen::Index r = 0; r < a.cols(); ++r) {
    for (MatrixD* f : {&a, &b}) {
      Eigen::Index at = 0;
      if (f->rows() == 0) continue;
      f->col(r).cwiseAbs().maxCoeff(&at);
      if ((*f)(at, r) < 0.0) {
        f->col(r) = -f->col(r);
        c.col(r) = -c.col(r);
      }
    }
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(a.cols()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index p, Eigen::Index q) { return c.col(p).norm() > c.col(q).norm(); });
  const MatrixD a0 = a, b0 = b, c0 = c;
  for (std::size_t r = 0; r < order.size(); ++r) {
    a.col(Eigen::Index(r)) = a0.col(order[r]);
    b.col(Eigen::Index(r)) = b0.col(order[r]);
    c.col(Eigen::Index(r)) = c0.col(order[r]);
  }
}

}  // namespace

Tensor3::Tensor3(int i, int j, int k)
    : I(i), J(j), K(k), values(static_cast<std::size_t>(std::max(i, 0)) * std::max(j, 0) * std::max(k, 0), 0.0f) {}

void CpSettings::validate() const {
  auto fail = [](const std::string& key, const std::string& value, const std::string& allowed) {
    throw InputError("CP decomposition: " + key + " = " + value + ": allowed " + allowed);
  };
  if (rank < 1 || rank > kMaxRank) fail("rank", std::to_string(rank), "1 .. " + std::to_string(kMaxRank));
  if (max_iterations < 1) fail("max_iterations", std::to_string(max_iterations), ">= 1");
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) fail("tolerance", std::to_string(tolerance), "a finite value >= 0");
  if (restarts < 1) fail("restarts", std::to_string(restarts), ">= 1");
}

float CpFactors::value(int i, int j, int k) const {
  return a.row(i).cwiseProduct(b.row(j)).dot(c.row(k));
}

CpFactors decompose(const Tensor3& x, const CpSettings& settings) {
  settings.validate();
  if (x.I < 0 || x.J < 0 || x.K < 0 ||
      x.values.size() != static_cast<std::size_t>(x.I) * static_cast<std::size_t>(x.J) * static_cast<std::size_t>(x.K))
    throw InputError("CP decomposition: tensor of " + std::to_string(x.I) + " x " + std::to_string(x.J) + " x " +
                     std::to_string(x.K) + " holds " + std::to_string(x.values.size()) +
                     " values: allowed sizes >= 0 and exactly I J K values");
  for (std::size_t n = 0; n < x.values.size(); ++n)
    if (!std::isfinite(x.values[n]))
      throw InputError("CP decomposition: value " + std::to_string(x.values[n]) + " at index " + std::to_string(n) +
                       ": allowed finite values");

  const int R = settings.rank;
  CpFactors out;
  out.rank = R;
  out.nonnegative = settings.nonnegative;
  out.a = Eigen::MatrixXf::Zero(x.I, R);
  out.b = Eigen::MatrixXf::Zero(x.J, R);
  out.c = Eigen::MatrixXf::Zero(x.K, R);
  const Unfolded unfolded = unfold(x);
  if (!(unfolded.norm_squared > 0.0)) return out;  // empty or all zero: the zero model is exact

  std::mt19937 rng(settings.seed);
  Fitter fitter(unfolded, settings);
  double best = std::numeric_limits<double>::infinity();
  for (int restart = 0; restart < settings.restarts; ++restart) {
    MatrixD a(x.I, R), b(x.J, R);
    if (settings.init == CpInit::nvecs && restart == 0) {
      a = leading_vectors(unfolded, 0, R, settings.nonnegative, rng);
      b = leading_vectors(unfolded, 1, R, settings.nonnegative, rng);
    } else {
      fill_uniform(a, rng);
      fill_uniform(b, rng);
    }
    Fit fit = fitter.run(std::move(a), std::move(b));
    canonicalise(fit.a, fit.b, fit.c);  // nonnegative factors: only the order changes
    const Eigen::MatrixXf af = fit.a.cast<float>(), bf = fit.b.cast<float>(), cf = fit.c.cast<float>();
    const double error = std::sqrt(residual_squared(unfolded, af, bf, cf) / unfolded.norm_squared);
    if (error < best) {
      best = error;
      out.a = af;
      out.b = bf;
      out.c = cf;
      out.relative_error = error;
      out.iterations = fit.iterations;
      out.error_history = std::move(fit.history);
    }
  }
  return out;
}

FactorPrefixSums::FactorPrefixSums(const Eigen::MatrixXf& f, bool nonneg)
    : factor(f), sums(f.rows() + 1, f.cols()), nonnegative(nonneg) {
  for (Eigen::Index r = 0; r < f.cols(); ++r) {
    double running = 0.0;
    sums(0, r) = 0.0f;
    for (Eigen::Index x = 0; x < f.rows(); ++x) {
      running += double(f(x, r));
      sums(x + 1, r) = static_cast<float>(running);
    }
  }
}

float FactorPrefixSums::integral_to(float t, int r) const {
  const int n = size();
  t = std::clamp(t, 0.0f, static_cast<float>(n));
  const float cell = std::floor(t);
  const int x = static_cast<int>(cell);
  if (x >= n) return sums(n, r);
  return sums(x, r) + (t - cell) * factor(x, r);
}

float FactorPrefixSums::range_sum(float t0, float t1, int r) const {
  const float s = integral_to(t1, r) - integral_to(t0, r);
  return nonnegative ? std::max(s, 0.0f) : s;
}

CpRangeQuery::CpRangeQuery(const CpFactors& f) : a(f.a, f.nonnegative), b(f.b, f.nonnegative), c(f.c) {}

float CpRangeQuery::range_sum(float i0, float i1, float j0, float j1, int k) const {
  float total = 0.0f;
  for (Eigen::Index r = 0; r < c.cols(); ++r) {
    const int rr = static_cast<int>(r);
    total += a.range_sum(i0, i1, rr) * b.range_sum(j0, j1, rr) * c(k, r);
  }
  return total;
}

}  // namespace glintlab
