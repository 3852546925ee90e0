#pragma once
// One backend's convergence: its error against a truth at rising samples per pixel, with the time
// each took (`glintlab converge` measures them, src/eval/convergence.hpp; `glintlab report` reads
// them back from convergence.json).
#include <string>
#include <vector>

namespace glintlab {

struct ConvergencePoint {
  int spp = 0;
  double seconds = 0;        ///< wall clock of the render, programs compiled beforehand
  double rmse = 0;           ///< of total radiance against the truth
  double relative_rmse = 0;  ///< rmse over the truth's mean
  double flip_hdr = 0;       ///< mean HDR-FLIP against the truth (core/flip.hpp), the truth's exposures
};

struct ConvergenceCurve {
  std::string backend;
  std::vector<ConvergencePoint> points;
  double seconds_to_target = 0;  ///< time to the target error (log-log interpolated); NaN if not reached
};

/// Seconds for a curve to reach `rmse`: interpolated in log-log between the points around its
/// first crossing, the first point's seconds if that one is already below; NaN if never reached.
double seconds_to_error(const std::vector<ConvergencePoint>& points, double rmse);

/// The curves' plots as SVG (log-log, the truth's noise a dashed floor); `of` ends their titles.
struct ConvergencePlots {
  std::string by_time, by_samples;
};
ConvergencePlots convergence_plots(const std::vector<ConvergenceCurve>& curves, double truth_noise_rmse,
                                   const std::string& of);

}  // namespace glintlab
