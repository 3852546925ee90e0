#pragma once
// A method as one self-contained GLSL file (`glintlab export`; docs/export.md): the expanded text
// of shaders/export/shade_pixel.frag in a method's, material kind's and light kind's variant, with
// the method's parameters as constants and nothing left to include, and what the file reads.
#include <string>
#include <vector>

#include "gl/driver_profile.hpp"
#include "shading/method_list.hpp"

namespace glintlab {

struct LightKind;
struct MaterialVariant;

/// A precomputed table the exported shader samples: the sampler's name and binding, and the
/// registry's table (written beside the shader as <id>.table).
struct ExportedTable {
  std::string id, sampler;
  int binding = -1;
};

struct ExportedShader {
  std::string glsl;                    ///< the whole file: #version, structs, blocks, glintlabShade, main()
  std::vector<ExportedTable> tables;   ///< the tables the program declares
  std::vector<std::string> resources;  ///< per-scene resources it reads (not exported: glintlab makes them per scene)
};

/// Throws InputError where the method cannot be exported as asked (an environment light for a
/// method that does not shade one itself is fine: it falls back to the split sum, as in glintlab).
ExportedShader export_shader(const MethodChoice& method, const MaterialVariant& material, const LightKind& light,
                             DriverProfile profile);

}  // namespace glintlab
