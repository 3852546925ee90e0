#pragma once
// The README.md `glintlab export` writes beside a method's shader: its entry point, the blocks and
// textures the compiled code reads (from spirv-cross's reflection, so it lists exactly those), the
// tables' files and their layout, the parameters it was made with.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/exported_shader.hpp"

namespace glintlab {

struct MaterialKind;

struct ExportReadme {
  std::string stem;
  const MethodChoice& method;
  const MaterialKind& kind;
  const LightKind& light;
  const ExportedShader& shader;
  const std::vector<ExportedTable>& tables;  ///< those the compiled code samples
  const nlohmann::json& reflection;          ///< spirv-cross --reflect of the SPIR-V
};

std::string export_readme(const ExportReadme& r);

}  // namespace glintlab
