// FFT-speed sums of exponentials (src/core/exponential_sum.hpp) against the sum written out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/exponential_sum.hpp"

using namespace glintlab;
using Complex = ExponentialSum::Complex;

TEST(ExponentialSum, EqualsTheDirectSumAtPowerOfTwoAndOtherLengths) {
  // Power-of-two lengths take the radix-2 FFT, the others Bluestein's chirp-z transform.
  for (const int n : {1, 2, 3, 4, 5, 7, 12, 64, 100, 127, 256}) {
    std::mt19937 rng(static_cast<unsigned>(n));
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    std::vector<Complex> data(static_cast<std::size_t>(n)), scratch;
    for (auto& c : data) c = {uni(rng), uni(rng)};
    const std::vector<Complex> input = data;
    const ExponentialSum sum(n);
    sum.evaluate(data, scratch);
    sum.evaluate(data = input, scratch);  // the scratch of an earlier call is reused safely
    for (int x = 0; x < n; ++x) {
      Complex expected(0.0);
      for (int k = 0; k < n; ++k) {
        const double angle = 2.0 * std::numbers::pi * static_cast<double>((static_cast<long long>(k) * x) % n) / n;
        expected += input[k] * Complex(std::cos(angle), std::sin(angle));
      }
      EXPECT_LT(std::abs(data[x] - expected), 1e-12 * n) << "n " << n << ", x " << x;
    }
  }
}
