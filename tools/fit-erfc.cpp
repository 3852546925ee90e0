// Fits the cheap erfc of shaders/glints/normal-map/position_normal.glsl (erfcPositive):
//   erfc(x) ~ exp(-x^2) t P(t),  t = 1 / (1 + p x),  P of degree n,
// for the least maximum relative error over x in [0, 12] (float's exp(-x^2) is 0 past 9.3), by
// iteratively reweighted least squares (Lawson's algorithm) for each p on a 0.01 grid.
// Build and run (Eigen from Debian's libeigen3-dev):
//   g++ -O2 -I/usr/include/eigen3 tools/fit-erfc.cpp -o /tmp/fit-erfc && /tmp/fit-erfc 5
// Prints p, the maximum relative error and P's coefficients from t^0 up.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

struct Fit {
  double p = 0, max_relative_error = 1;
  Eigen::VectorXd coefficients;
};

double polynomial(const Eigen::VectorXd& c, double t) {
  double sum = 0;
  for (int k = static_cast<int>(c.size()) - 1; k >= 0; --k) sum = sum * t + c(k);
  return sum;
}

Fit fit(int degree, double p) {
  std::vector<double> xs, targets;  // P(t) = erfc(x) exp(x^2) / t at 4001 points of [0, 12]
  for (int i = 0; i <= 4000; ++i) {
    const double x = 12.0 * i / 4000.0, t = 1 / (1 + p * x);
    xs.push_back(x);
    targets.push_back(std::erfc(x) * std::exp(x * x) / t);
  }
  std::vector<double> weights(xs.size(), 1.0);
  Fit f{p, 0, {}};
  for (int iteration = 0; iteration < 60; ++iteration) {
    Eigen::MatrixXd a(xs.size(), degree + 1);
    Eigen::VectorXd b(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {  // relative residuals, weighted
      const double t = 1 / (1 + p * xs[i]);
      double tk = 1;
      for (int k = 0; k <= degree; ++k, tk *= t) a(i, k) = weights[i] * tk / targets[i];
      b(i) = weights[i];
    }
    f.coefficients = a.colPivHouseholderQr().solve(b);
    std::vector<double> errors(xs.size());
    f.max_relative_error = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      errors[i] = std::abs(polynomial(f.coefficients, 1 / (1 + p * xs[i])) / targets[i] - 1);
      f.max_relative_error = std::max(f.max_relative_error, errors[i]);
    }
    for (std::size_t i = 0; i < xs.size(); ++i) weights[i] *= std::pow(errors[i] / f.max_relative_error + 1e-3, 0.3);
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const int degree = argc > 1 ? std::atoi(argv[1]) : 5;
  Fit best;
  for (int i = 30; i <= 70; ++i) {
    Fit f = fit(degree, i / 100.0);
    if (f.max_relative_error < best.max_relative_error) best = f;
  }
  std::printf("degree %d, p %.2f, max relative error %.3e\ncoefficients:", degree, best.p, best.max_relative_error);
  for (double c : best.coefficients) std::printf(" %.10g", c);
  std::printf("\n");
}
