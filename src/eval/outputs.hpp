#pragma once
// Writing rendered frames: a linear EXR (main layer = total radiance, layer "specular") and a
// tonemapped sRGB PNG for people to look at; and the run's description every metrics file carries.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/file_access.hpp"  // check_output_directory, check_output_file
#include "core/metrics.hpp"
#include "eval/session.hpp"
#include "render/renderer.hpp"

namespace glintlab {

/// Where `render -o PATH` writes: <dir>/<stem>.exr and <dir>/<stem>.png.
struct FrameOutput {
  std::filesystem::path dir;
  std::string stem;
};
/// PATH ending in .exr or .png (any case) names the two files beside each other; a path without an
/// extension is a directory that gets <default_stem>.exr/.png. Checked before anything is rendered:
/// throws InputError for another extension, for a target file that exists as a directory, and for
/// a folder on the way that exists as a file.
FrameOutput frame_output(const std::string& path, const std::string& default_stem);

/// Writes <dir>/<stem>.exr and <dir>/<stem>.png.
void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film);
/// The same for a reference, whose EXR also holds its per-pixel standard error ("standard_error").
void write_reference(const std::filesystem::path& dir, const std::string& stem, const ReferenceFrame& reference,
                     const Film& film);
/// The keys that describe a run in every metrics file (compare's and animate's metrics.json,
/// bench.json): the scene as given, the image size and the GL device. Each command adds its own.
nlohmann::json run_metadata(Session& session);
/// How compare and animate look at images for FLIP: the film's exposure, --ppd (or the default).
MetricsViewing metrics_viewing(const Session& session);
/// What two independent halves of a reference score against each other (its even passes against
/// its odd ones): FLIP and the sparkle distance of its own noise at half its samples, the floor
/// below which a difference between methods is noise. Zero with fewer than two passes.
ImageMetrics half_reference_floor(const ReferenceFrame& reference, const MetricsViewing& viewing);
/// One line on what a reference reached: samples, passes, noise RMSE, energy error.
std::string describe_reference(const ReferenceFrame& reference);

}  // namespace glintlab
