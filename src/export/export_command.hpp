#pragma once
// `glintlab export` (docs/export.md): one method as a self-contained shader an engine can lift:
// <stem>.glsl (Vulkan-style GLSL 4.50, the entry point glintlabShade and an example main), its
// SPIR-V, HLSL and MSL translations (glslangValidator and spirv-cross, Debian's glslang-tools and
// spirv-cross), the tables it samples as <id>.table files and a README.md on binding them.
#include <string>
#include <vector>

namespace glintlab {

struct ExportOptions {
  std::string method = "conventional";  ///< a method or variant (--methods syntax)
  std::vector<std::string> params;      ///< --param
  std::string material_kind;            ///< empty: the default kind
  bool normal_map = false, textures = false, anisotropic = false;
  std::string light = "point";               ///< the light kind glintlabShade takes
  std::string driver_profile = "hardware";  ///< engines run on GPUs (docs/methods.md, "Driver profiles")
  std::string out;                           ///< the directory
};

/// Writes the export into `options.out` as a unit (nothing on failure); returns the files' names.
/// Throws InputError for a bad option (before anything is written), RuntimeFailure when a tool is
/// missing or fails.
std::vector<std::string> run_export(const ExportOptions& options);

}  // namespace glintlab
