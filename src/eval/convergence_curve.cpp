#include "eval/convergence_curve.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "eval/report_svg.hpp"

namespace glintlab {

double seconds_to_error(const std::vector<ConvergencePoint>& points, double rmse) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].rmse > rmse) continue;
    if (i == 0) return points[0].seconds;
    const ConvergencePoint& a = points[i - 1];
    const ConvergencePoint& b = points[i];
    // Between two points error and time follow a power law: a line in log-log.
    const double t = (std::log(a.rmse) - std::log(rmse)) / (std::log(a.rmse) - std::log(b.rmse));
    return std::exp(std::log(a.seconds) + t * (std::log(b.seconds) - std::log(a.seconds)));
  }
  return std::numeric_limits<double>::quiet_NaN();
}

ConvergencePlots convergence_plots(const std::vector<ConvergenceCurve>& curves, double truth_noise_rmse,
                                   const std::string& of) {
  std::vector<PointSeries> by_time, by_samples;
  char seconds[32];
  for (const ConvergenceCurve& curve : curves) {
    PointSeries t{curve.backend, {}}, n{curve.backend, {}};
    for (const ConvergencePoint& p : curve.points) {
      std::snprintf(seconds, sizeof seconds, "%.3g s", p.seconds);
      t.points.push_back({p.seconds, p.rmse, std::to_string(p.spp) + " spp"});
      n.points.push_back({static_cast<double>(p.spp), p.rmse, seconds});
    }
    by_time.push_back(std::move(t));
    by_samples.push_back(std::move(n));
  }
  const std::vector<PlotMark> floor = {{"the truth's noise", truth_noise_rmse}};
  return {log_log_plot_svg("error against time, " + of, "seconds", "RMSE", by_time, floor),
          log_log_plot_svg("error against samples, " + of, "samples per pixel", "RMSE", by_samples, floor)};
}

}  // namespace glintlab
