#include "eval/environment_fit_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "prefilter/environment_sg_fit.hpp"

namespace glintlab {

namespace {

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

void run_environment_fit_report(const Scene& scene, const EnvironmentFitOptions& options) {
  const EnvironmentMap* map = nullptr;
  for (const Light& l : scene.lights)
    if (l.environment) map = l.environment.get();
  if (!map) throw InputError(scene.source + ": the scene has no environment light; allowed: a scene with one");
  const int rows = std::min(options.grid_height, map->radiance.height());
  std::printf("environment %s, %d x %d texels, fitted on %d rows\n\n", map->source.c_str(), map->radiance.width(),
              map->radiance.height(), rows);
  std::printf("| lobes | peaks | their power | their sharpness | the lattice's sharpness | relative L2 | seconds |\n"
              "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  SphericalGaussianFit last;
  for (int k : options.lobes) {
    const auto start = std::chrono::steady_clock::now();
    last = fit_spherical_gaussians(*map, k, rows);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The peaks' share of the fit's luminance power, and their sharpness range.
    const std::vector<double> p = last.lobe_probabilities();
    double share = 0.0, sharpest = 0.0, softest = HUGE_VAL;
    for (int j = 0; j < last.peaks; ++j) {
      share += p[static_cast<std::size_t>(j)];
      sharpest = std::max(sharpest, last.lobes[static_cast<std::size_t>(j)].sharpness);
      softest = std::min(softest, last.lobes[static_cast<std::size_t>(j)].sharpness);
    }
    const std::string peaks_sharpness =
        last.peaks == 0 ? "-" : softest == sharpest ? format_number(sharpest) : format_number(softest) + " .. " + format_number(sharpest);
    std::printf("| %d | %d | %.1f%% | %s | %.3g | %.4f | %.2f |\n", k, last.peaks, 100.0 * share, peaks_sharpness.c_str(),
                last.lobes.back().sharpness, last.relative_error, seconds);
  }
  if (!options.out_exr.empty()) {
    const EnvironmentMap fitted = last.to_map(map->radiance.height());
    write_exr(options.out_exr, {{"", &fitted.radiance}});
    std::printf("\nwrote %s: the %zu-lobe fit as a %d x %d map\n", options.out_exr.string().c_str(), last.lobes.size(),
                fitted.radiance.width(), fitted.radiance.height());
  }
}

}  // namespace glintlab
