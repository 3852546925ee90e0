#pragma once
// 3-way CP (canonical polyadic) decomposition of a block of NDF images, and the 1D prefix sums of
// its factors that turn a box of the NDF into R products (Deng et al. 2022's range query).
//
//   X[i, j, k] ~ sum_r a(i, r) b(j, r) c(k, r)      (Kolda & Bader 2009, eq. 3.2, weights in c)
//
// i and j are the small angular modes (one NDF block, 8..32 texels a side), k the long mode (the
// positions or footprints stacked, 1..4096). Fitted by alternating least squares (Kolda & Bader
// section 3.4) or, by default, by nonnegative HALS (Cichocki & Phan 2009), which keeps every
// factor >= 0 and so every reconstructed value and every range sum >= 0, as an NDF is.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace glintlab {

/// A dense I x J x K tensor of floats, stored row-major: values[(i * J + j) * K + k], so the
/// long mode k is contiguous and X seen as an (I J) x K matrix needs no copy.
struct Tensor3 {
  int I = 0, J = 0, K = 0;
  std::vector<float> values;

  Tensor3() = default;
  Tensor3(int i, int j, int k);  ///< all zeros
  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * static_cast<std::size_t>(J) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(K) + static_cast<std::size_t>(k);
  }
  [[nodiscard]] float at(int i, int j, int k) const { return values[index(i, j, k)]; }
  float& at(int i, int j, int k) { return values[index(i, j, k)]; }
};

enum class CpInit {
  random,  ///< a and b uniform in [0, 1): never negative, the usual start for nonnegative data
  nvecs,   ///< a and b the leading eigenvectors of the mode's unfolding X_(n) X_(n)^T (absolute
           ///< values when nonnegative), padded with random columns past the mode's size
};

struct CpSettings {
  int rank = 16;              ///< R, 1 .. kMaxRank; may exceed a mode's size
  int max_iterations = 500;   ///< sweeps over the three modes, per restart
  double tolerance = 1e-5;    ///< stop when the relative error changes by less than this in a sweep
  bool nonnegative = true;    ///< HALS with every factor >= 0; false: unconstrained ALS
  std::uint32_t seed = 1;     ///< of the random starts (std::mt19937); same seed, same bits
  int restarts = 1;           ///< random starts; the one with the lowest final error is kept
  CpInit init = CpInit::random;

  static constexpr int kMaxRank = 256;
  /// Throws InputError naming the setting, its value and what is allowed.
  void validate() const;
};

/// The decomposition. a and b have unit-length columns (or zero ones); c carries the weights, so
/// value(i, j, k) = sum_r a(i, r) b(j, r) c(k, r). Components are sorted by weight, largest first.
struct CpFactors {
  int rank = 0;
  Eigen::MatrixXf a;  ///< I x R
  Eigen::MatrixXf b;  ///< J x R
  Eigen::MatrixXf c;  ///< K x R
  bool nonnegative = false;  ///< every entry of a, b, c >= 0 (fitted with HALS)
  /// ||X - X^|| / ||X|| of the float factors above, computed explicitly in double; 0 when X = 0.
  double relative_error = 0.0;
  int iterations = 0;  ///< sweeps done by the kept restart
  /// The relative error after each sweep of the kept restart (from the Gram identity
  /// ||X - X^||^2 = ||X||^2 - 2 <X, X^> + ||X^||^2 in double; the last entry may differ from
  /// relative_error by the rounding of the factors to float).
  std::vector<double> error_history;

  [[nodiscard]] float value(int i, int j, int k) const;
};

/// Fits a rank-R CP model to x. An empty or all-zero x gives zero factors of the right sizes and
/// relative error 0 (no iterations). Deterministic: no threads, a fixed seed.
/// Throws InputError for bad settings or a tensor whose size does not match I J K or that holds
/// a non-finite value.
[[nodiscard]] CpFactors decompose(const Tensor3& x, const CpSettings& settings);

/// The exclusive prefix sums of each column of a factor m (n x R): sums (n + 1) x R with
/// sums(0, r) = 0 and sums(x + 1, r) = sums(x, r) + m(x, r), accumulated in double, stored float.
/// The column as a piecewise-constant function of a continuous coordinate t in [0, n] (texel x
/// covers [x, x + 1)) has the integral S(t) = sums(floor t, r) + frac(t) m(floor t, r) from 0 to t.
struct FactorPrefixSums {
  Eigen::MatrixXf factor;  ///< n x R
  Eigen::MatrixXf sums;    ///< (n + 1) x R
  /// Clamp every range sum at 0. Set for nonnegative factors, where a range sum can only come
  /// out below 0 by float rounding (of a near-empty range next to a texel edge).
  bool nonnegative = false;

  FactorPrefixSums() = default;
  FactorPrefixSums(const Eigen::MatrixXf& factor, bool nonnegative);

  [[nodiscard]] int size() const { return static_cast<int>(factor.rows()); }
  /// S(t) of column r; t is clamped to [0, n], and S(n) = sums(n, r).
  [[nodiscard]] float integral_to(float t, int r) const;
  /// The integral of column r over [t0, t1] (t0 <= t1; clamped to [0, n]): S(t1) - S(t0).
  [[nodiscard]] float range_sum(float t0, float t1, int r) const;
};

/// The prefix sums of both angular factors of a decomposition, for box queries.
struct CpRangeQuery {
  FactorPrefixSums a, b;
  Eigen::MatrixXf c;  ///< K x R, a copy of the factors' c

  explicit CpRangeQuery(const CpFactors& factors);
  /// The integral of the piecewise-constant reconstruction over the box [i0, i1] x [j0, j1]
  /// (continuous texel coordinates) in slice k:
  ///   sum_r (SA(i1) - SA(i0)) (SB(j1) - SB(j0)) c(k, r).
  /// Over whole texels it is the sum of value(i, j, k) for i0 <= i < i1, j0 <= j < j1.
  [[nodiscard]] float range_sum(float i0, float i1, float j0, float j1, int k) const;
};

}  // namespace glintlab
