#include "core/exponential_sum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace glintlab {

namespace {

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

/// exp(i pi num / den), the argument reduced first so large num loses no precision.
std::complex<double> unit_phase(long long num, long long den) {
  num %= 2 * den;
  const double a = std::numbers::pi * static_cast<double>(num) / static_cast<double>(den);
  return {std::cos(a), std::sin(a)};
}

/// a * w (sign +1) or a * conj(w) (sign -1), written out: std::complex's operator* checks for
/// NaN and infinity (a library call per product) unless compiled with -ffast-math.
std::complex<double> times(std::complex<double> a, std::complex<double> w, int sign) {
  const double wi = sign * w.imag();
  return {a.real() * w.real() - a.imag() * wi, a.real() * wi + a.imag() * w.real()};
}

}  // namespace

ExponentialSum::ExponentialSum(int n) : n_(n), m_(1) {
  const bool direct = is_power_of_two(n);
  // Bluestein's convolution has 2N - 1 nonzero taps: its FFTs need at least that length.
  while (m_ < (direct ? n : 2 * n - 1)) m_ *= 2;
  // Each stage's twiddles side by side (stage `half` at [half - 1, 2 half - 1)), so the butterflies
  // read them in order; each one computed directly, not by a recurrence.
  twiddles_.resize(static_cast<std::size_t>(std::max(1, m_ - 1)));
  for (int half = 1; half < m_; half <<= 1)
    for (int k = 0; k < half; ++k) twiddles_[half - 1 + k] = unit_phase(k, half);
  if (direct) return;
  // k x = (k^2 + x^2 - (x - k)^2) / 2, so exp(2 pi i k x / N) = c_k c_x conj(c_{x-k}) with
  // c_j = exp(i pi j^2 / N): the sum is c_x times the convolution of (data_k c_k) with conj(c).
  chirp_.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) chirp_[j] = unit_phase(static_cast<long long>(j) * j, n);
  chirp_fft_.assign(static_cast<std::size_t>(m_), Complex(0.0));
  for (int j = 0; j < n; ++j) {
    chirp_fft_[j] = std::conj(chirp_[j]);
    if (j > 0) chirp_fft_[m_ - j] = std::conj(chirp_[j]);  // negative lags, wrapped
  }
  fft(chirp_fft_, -1);
}

void ExponentialSum::fft(std::vector<Complex>& a, int sign) const {
  const int m = m_;
  for (int i = 1, j = 0; i < m; ++i) {  // bit-reversal permutation
    int bit = m >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (int half = 1; half < m; half <<= 1) {
    const Complex* w = twiddles_.data() + (half - 1);  // this stage's exp(i pi k / half)
    for (int start = 0; start < m; start += 2 * half)
      for (int k = 0; k < half; ++k) {
        const Complex u = a[start + k], v = times(a[start + k + half], w[k], sign);
        a[start + k] = u + v;
        a[start + k + half] = u - v;
      }
  }
}

void ExponentialSum::evaluate(std::vector<Complex>& data, std::vector<Complex>& scratch) const {
  if (chirp_.empty()) {
    fft(data, +1);
    return;
  }
  scratch.assign(static_cast<std::size_t>(m_), Complex(0.0));
  for (int k = 0; k < n_; ++k) scratch[k] = times(data[k], chirp_[k], +1);
  fft(scratch, -1);
  for (int j = 0; j < m_; ++j) scratch[j] = times(scratch[j], chirp_fft_[j], +1);
  fft(scratch, +1);  // the inverse FFT of the product, times m_
  const double inv_m = 1.0 / m_;
  for (int x = 0; x < n_; ++x) data[x] = times(scratch[x], chirp_[x], +1) * inv_m;
}

}  // namespace glintlab
