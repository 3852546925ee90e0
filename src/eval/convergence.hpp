#pragma once
// `glintlab converge`: how fast backends' images approach a truth, in samples and in seconds.
// Each backend (a ground truth, or a method in the path tracer: path:deng2022{...}) renders the
// frame at a rising number of samples per pixel, each step from seeds of its own, timed by the
// wall clock after a warm-up pass; each image's RMSE against the truth (a backend at many samples)
// is one point of its curve. The error falls as 1/sqrt(samples) while noise rules it and levels
// off at the backend's bias against the truth; how soon a curve reaches an error is the time to
// equal error Deng et al. 2022 report against Yan et al. 2016 (sec. 6), and lobes against sampling
// under an environment (their fig. 11).
#include <filesystem>
#include <string>
#include <vector>

#include "eval/convergence_curve.hpp"
#include "eval/session.hpp"

namespace glintlab {

struct ConvergeOptions {
  std::string backends;       ///< --backends: ids separated by commas (variants' braces kept together)
  std::vector<int> steps;     ///< --steps: samples per pixel of each point, rising
  int light_samples = 1;      ///< per sub-pixel and light with extent, at every step
  int frame = 0;
};

struct Convergence {
  std::vector<ConvergenceCurve> curves;
  double truth_noise_rmse = 0;  ///< the truth's own noise: errors near it are not resolved
  double truth_mean = 0;
  double target_rmse = 0;       ///< the lowest error every curve reaches: the largest of their smallest
};

/// Renders every backend's steps against the session's reference (its --reference-backend at its
/// --spp: the truth), prints the table and writes convergence.json, convergence.csv and
/// convergence.svg (error against seconds and against samples) under `out`.
Convergence run_converge(Session& session, const ConvergeOptions& options, const std::filesystem::path& out);

/// Checks --backends and --steps before any GL work; throws InputError naming the flag, the value
/// and what is allowed. Returns the backend ids.
std::vector<std::string> check_converge_options(const ConvergeOptions& options);

}  // namespace glintlab
