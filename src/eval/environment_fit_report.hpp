#pragma once
// `glintlab environment-fit`: a scene's environment fitted by spherical Gaussian lobes as deng2022
// shades it (src/prefilter/environment_sg_fit.hpp; Deng et al. 2022 sec. 5.4), reported for each
// lobe count (sharpness, relative L2 over the sphere, time), and on request written out as a map:
// a scene whose environment is that file is the truth of the lobes' shading without the fit's error.
#include <filesystem>
#include <vector>

#include "prefilter/environment_sg_fit.hpp"
#include "scene/scene.hpp"

namespace glintlab {

struct EnvironmentFitOptions {
  std::vector<int> lobes = {8, 16, 32, 48};
  int grid_height = kSphericalGaussianFitRows;  ///< the rows the map is fitted on (the methods'); at most the map's
  std::filesystem::path out_exr;  ///< the fit with the last lobe count, as a lat-long EXR (when set)
};

/// Prints a Markdown table to stdout. Throws InputError when the scene has no environment light.
void run_environment_fit_report(const Scene& scene, const EnvironmentFitOptions& options);

}  // namespace glintlab
