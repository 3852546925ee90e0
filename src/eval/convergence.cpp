#include "eval/convergence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/metrics.hpp"
#include "core/output_stage.hpp"
#include "eval/outputs.hpp"
#include "eval/progress.hpp"
#include "shading/method_list.hpp"

namespace glintlab {

namespace {

/// Seeds no other step, curve or the truth (seed = frame) draws: every point is independent of the
/// truth and of the others, so an error is not understated by shared samples.
int step_seed(int frame, std::size_t curve, std::size_t step) {
  return frame + 7919 * static_cast<int>(1 + curve * 256 + step);
}

std::string fixed(double v, const char* format = "%.4g") {
  char s[32];
  std::snprintf(s, sizeof s, format, v);
  return s;
}

std::string table(const Convergence& c) {
  std::ostringstream s;
  s << "| backend | spp | seconds | rmse | relative rmse | HDR-FLIP |\n| --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& curve : c.curves)
    for (const auto& p : curve.points)
      s << "| " << curve.backend << " | " << p.spp << " | " << fixed(p.seconds, "%.3f") << " | " << fixed(p.rmse)
        << " | " << fixed(p.relative_rmse) << " | " << fixed(p.flip_hdr) << " |\n";
  s << "\ntime to rmse " << fixed(c.target_rmse) << " (the lowest error every curve reaches):\n";
  const double first = c.curves.front().seconds_to_target;
  for (const auto& curve : c.curves)
    s << "  " << curve.backend << ": " << fixed(curve.seconds_to_target, "%.3f") << " s"
      << (&curve == &c.curves.front() ? "" : ", x" + fixed(curve.seconds_to_target / first, "%.3g") + " of the first")
      << "\n";
  return s.str();
}

}  // namespace

std::vector<std::string> check_converge_options(const ConvergeOptions& options) {
  const std::vector<std::string> ids = split_outside_braces(options.backends, "--backends '" + options.backends + "'");
  for (const std::string& id : ids) {
    if (id.empty()) throw InputError("--backends '" + options.backends + "': an empty entry; allowed: backend ids separated by commas (see 'glintlab info')");
    find_reference_backend(id);
  }
  if (options.steps.empty()) throw InputError("--steps: none given; allowed: rising samples per pixel, e.g. 1,4,16,64");
  for (std::size_t i = 0; i < options.steps.size(); ++i) {
    validate_spp(options.steps[i]);
    if (i > 0 && options.steps[i] <= options.steps[i - 1])
      throw InputError("--steps: " + std::to_string(options.steps[i]) + " after " + std::to_string(options.steps[i - 1]) +
                       "; allowed: rising samples per pixel, e.g. 1,4,16,64");
  }
  if (options.light_samples < 1 || options.light_samples > 4096)
    throw InputError("--light-samples " + std::to_string(options.light_samples) + ": allowed: 1 .. 4096 with converge");
  return ids;
}

Convergence run_converge(Session& session, const ConvergeOptions& options, const std::filesystem::path& out) {
  const std::vector<std::string> ids = check_converge_options(options);
  const Camera camera = session.camera(options.frame);
  const int width = session.width(), height = session.height();

  Convergence result;
  const ReferenceFrame truth = session.reference(options.frame);
  result.truth_noise_rmse = truth.noise_rmse();
  const glm::dvec3 mean = truth.mean.total.mean();
  result.truth_mean = (mean.r + mean.g + mean.b) / 3.0;
  const MetricsViewing viewing = metrics_viewing(session);
  const flip::HdrReference perceived_truth(truth.mean.total, viewing.pixels_per_degree,
                                           flip::automatic_exposures(truth.mean.total));

  for (std::size_t c = 0; c < ids.size(); ++c) {
    ConvergenceCurve curve{.backend = ids[c]};
    auto backend = make_reference_backend(ids[c], session.backend_context());
    ReferenceSettings settings = session.reference_settings();
    settings.light_samples = options.light_samples;
    {
      // Warm-up: the programs compiled and the resources built before anything is timed.
      ReferenceSettings warm = settings;
      warm.spp = 1;
      warm.seed = step_seed(options.frame, c, 255);
      render_reference(*backend, camera, width, height, warm);
    }
    ProgressBar bar("converge " + ids[c], !session.options().quiet, "steps");
    for (std::size_t s = 0; s < options.steps.size(); ++s) {
      settings.spp = options.steps[s];
      settings.seed = step_seed(options.frame, c, s);
      const auto start = std::chrono::steady_clock::now();
      const ReferenceFrame frame = render_reference(*backend, camera, width, height, settings);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      require_finite(frame.mean, ids[c] + " at " + std::to_string(settings.spp) + " spp");
      const double error = rmse(frame.mean.total, truth.mean.total);
      curve.points.push_back({settings.spp, seconds, error, error / result.truth_mean,
                              flip::mean(perceived_truth.error_map(frame.mean.total))});
      bar.update(static_cast<int>(s + 1), static_cast<int>(options.steps.size()));
    }
    result.curves.push_back(std::move(curve));
  }
  for (const auto& curve : result.curves) {
    double lowest = curve.points.front().rmse;
    for (const auto& p : curve.points) lowest = std::min(lowest, p.rmse);
    result.target_rmse = std::max(result.target_rmse, lowest);
  }
  for (auto& curve : result.curves) curve.seconds_to_target = seconds_to_error(curve.points, result.target_rmse);

  // Outputs, published as a unit with the JSON last.
  nlohmann::json json = run_metadata(session);
  json["frame"] = options.frame;
  json["truth_spp"] = truth.spp;
  json["truth_noise_rmse"] = result.truth_noise_rmse;
  json["truth_mean"] = result.truth_mean;
  json["light_samples"] = options.light_samples;
  json["target_rmse"] = result.target_rmse;
  json["truth_backend"] = session.reference_backend().id();
  std::ostringstream csv;
  csv << "backend,spp,seconds,rmse,relative_rmse,flip_hdr\n";
  for (const auto& curve : result.curves) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : curve.points) {
      points.push_back({{"spp", p.spp},
                        {"seconds", p.seconds},
                        {"rmse", p.rmse},
                        {"relative_rmse", p.relative_rmse},
                        {"flip_hdr", p.flip_hdr}});
      csv << curve.backend << "," << p.spp << "," << p.seconds << "," << p.rmse << "," << p.relative_rmse << ","
          << p.flip_hdr << "\n";
    }
    json["curves"].push_back({{"backend", curve.backend},
                              {"points", points},
                              {"seconds_to_target", std::isfinite(curve.seconds_to_target)
                                                        ? nlohmann::json(curve.seconds_to_target)
                                                        : nlohmann::json(nullptr)}});
  }
  const std::string truth_name = session.reference_backend().id() + " at " + std::to_string(truth.spp) + " spp";
  const ConvergencePlots plots =
      convergence_plots(result.curves, result.truth_noise_rmse, session.scene().source + " (truth: " + truth_name + ")");
  OutputStage stage(out);
  write_reference(stage.path(), "truth", truth, session.scene().film);
  write_text_file(stage.path() / "convergence.svg", plots.by_time);
  write_text_file(stage.path() / "convergence-spp.svg", plots.by_samples);
  write_text_file(stage.path() / "convergence.csv", csv.str());
  write_text_file(stage.path() / "convergence.json", json.dump(2) + "\n");
  stage.publish({"convergence.csv", "convergence.json"});
  std::cout << "scene " << session.scene().source << ", " << width << "x" << height << ", truth " << truth_name << ", "
            << describe_reference(truth) << "\n"
            << table(result) << "written to " << out.string() << "/\n";
  return result;
}

}  // namespace glintlab
