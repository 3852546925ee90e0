#pragma once
// Writing rendered frames: a linear EXR (main layer = total radiance, layer "specular") and a
// tonemapped sRGB PNG for people to look at.
#include <filesystem>
#include <string>

#include "render/renderer.hpp"

namespace glintlab {

/// Writes <dir>/<stem>.exr and <dir>/<stem>.png.
void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film);
/// The same for a reference, whose EXR also holds its per-pixel standard error ("standard_error").
void write_reference(const std::filesystem::path& dir, const std::string& stem, const ReferenceFrame& reference,
                     const Film& film);
/// One line on what a reference reached: samples, passes, noise RMSE, energy error.
std::string describe_reference(const ReferenceFrame& reference);

}  // namespace glintlab
