#pragma once
// Sums of complex exponentials at N equally spaced points (an unnormalised inverse DFT), in
// O(N log N) for any N: an iterative radix-2 FFT when N is a power of two, otherwise Bluestein's
// chirp-z transform, which turns the length-N sum into a convolution done by power-of-two FFTs.
#include <complex>
#include <vector>

namespace glintlab {

class ExponentialSum {
 public:
  using Complex = std::complex<double>;

  explicit ExponentialSum(int n);
  [[nodiscard]] int size() const { return n_; }

  /// In place: data[x] <- sum_k data[k] exp(2 pi i k x / N), for data of size N. `scratch` is
  /// working memory kept between calls (one per thread; this object is shared read-only).
  void evaluate(std::vector<Complex>& data, std::vector<Complex>& scratch) const;

 private:
  /// Radix-2 FFT of size m_ in place; sign +1: exp(+2 pi i k x / m), -1: exp(-...).
  void fft(std::vector<Complex>& a, int sign) const;

  int n_;
  int m_;                             ///< the power-of-two length the FFTs run at
  std::vector<Complex> twiddles_;     ///< per FFT stage of half-length h: exp(i pi k / h), k < h
  std::vector<Complex> chirp_;        ///< Bluestein only: exp(i pi j^2 / N), j < N
  std::vector<Complex> chirp_fft_;    ///< Bluestein only: FFT of the conjugate chirp, wrapped to m_
};

}  // namespace glintlab
