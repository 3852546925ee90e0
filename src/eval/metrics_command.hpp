#pragma once
// `glintlab metrics`: compare's numbers for two image files made anywhere (another renderer's
// frame against a glintlab reference, or two pictures).
#include <optional>
#include <string>

#include "core/flip.hpp"

namespace glintlab {

struct MetricsCommandOptions {
  std::string test, reference;  ///< both .exr (radiance) or both .png (display-encoded sRGB)
  double pixels_per_degree = 0;  ///< 0: flip::default_pixels_per_degree()
  float display_exposure = 0.0f;  ///< stops before the displayed picture's ACES curve (EXR inputs)
  std::optional<flip::Exposures> hdr_exposures;  ///< HDR-FLIP's range; default: automatic
  std::string flip_map;  ///< optional .png: the FLIP error map (HDR-FLIP for EXR inputs)
  std::string json;      ///< optional .json file: the metrics as JSON (stdout has them as lines)
};

/// Parses --hdr-exposures "START,STOP,COUNT" (START <= STOP, COUNT >= 2); throws InputError.
flip::Exposures parse_hdr_exposures(const std::string& text);

/// Reads both images, checks them (same kind, same size, finite values) and prints the metrics.
/// Throws InputError naming the file and what is wrong.
void run_metrics_command(const MetricsCommandOptions& options);

}  // namespace glintlab
