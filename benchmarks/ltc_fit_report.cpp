// Fits both LTC tables (src/tables/ltc/ltc_fit.hpp) as their generator does and prints, as markdown, how
// long each took and its fit error over the grid: the relative L1 distance of the LTC lobe from its
// target over l.z > 0 (ltc_fit_error, 2 x 64 x 64 samples per cell). docs/methods.md's tables come
// from here: `build/release/benchmarks/ltc_fit_report [threads]` (default: every hardware thread).
// Not a test: the times depend on the machine.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <thread>

#include "tables/ltc/ltc_table.hpp"

namespace {

using namespace glintlab;

void report(LtcTargetKind kind, const char* id, int threads) {
  const LtcFitSettings settings = ltc_table_fit_settings();
  const auto start = std::chrono::steady_clock::now();
  const LtcFit fit = fit_ltc_grid(kind, settings, {}, threads);
  const std::vector<float> values = ltc_table_values(fit);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<double> error = ltc_fit_error_grid(fit, 64);
  const int n = settings.size;

  std::printf("### %s\n\nGenerated (fit and layout) in %.1f s on %d threads.\n\n", id, seconds, threads);
  std::printf("Fit error (relative L1 over l.z > 0) at every 7th cell; rows theta_v, columns alpha:\n\n| theta_v |");
  for (int i = 0; i < n; i += 7) std::printf(" %.3g |", ltc_grid_alpha(i, settings));
  std::printf("\n| --- |");
  for (int i = 0; i < n; i += 7) std::printf(" --- |");
  std::printf("\n");
  for (int j = 0; j < n; j += 7) {
    std::printf("| %.1f |", std::acos(ltc_grid_cos_theta(j, settings)) * 180.0 / std::numbers::pi);
    for (int i = 0; i < n; i += 7) std::printf(" %.3f |", error[static_cast<std::size_t>(j * n + i)]);
    std::printf("\n");
  }
  // Maxima over regions of the whole grid.
  auto worst = [&](double max_theta_deg, double min_alpha) {
    double w = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (std::acos(ltc_grid_cos_theta(j, settings)) * 180.0 / std::numbers::pi <= max_theta_deg + 1e-9 &&
            ltc_grid_alpha(i, settings) >= min_alpha)
          w = std::max(w, error[static_cast<std::size_t>(j * n + i)]);
    return w;
  };
  double mean = 0.0;
  for (double e : error) mean += e / static_cast<double>(error.size());
  std::printf("\nOver all 4096 cells: mean %.3f, max %.3f; max with theta_v <= 30 deg %.3f, <= 60 deg %.3f, "
              "<= 75 deg %.3f; max at normal incidence %.3f.\n\n",
              mean, worst(90.0, 0.0), worst(30.0, 0.0), worst(60.0, 0.0), worst(75.0, 0.0), worst(0.0, 0.0));
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::max(1, std::atoi(argv[1]))
                               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  report(LtcTargetKind::Ggx, "ltc-ggx", threads);
  report(LtcTargetKind::Ndf, "ltc-ndf", threads);
  return 0;
}
