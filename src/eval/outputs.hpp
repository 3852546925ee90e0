#pragma once
// Writing rendered frames: a linear EXR (main layer = total radiance, layer "specular") and a
// tonemapped sRGB PNG for people to look at.
#include <filesystem>
#include <string>

#include "render/renderer.hpp"

namespace glintlab {

/// Writes <dir>/<stem>.exr and <dir>/<stem>.png.
void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film);

}  // namespace glintlab
