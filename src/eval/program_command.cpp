#include "eval/program_command.hpp"

#include "core/error.hpp"
#include "shading/method_list.hpp"
#include "render/program_text.hpp"
#include "render/shader_contract.hpp"
#include "scene/materials/material_kind.hpp"

namespace glintlab {

std::string program_module(ShaderLibrary& shaders, const std::string& method, const std::vector<std::string>& params) {
  for (const ProgramPass& pass : kProgramPasses)
    if (method == pass.name) return pass.module;
  std::vector<MethodChoice> choices;
  try {
    choices = resolve_methods(method, params);
  } catch (const InputError& e) {
    std::string passes;
    for (const ProgramPass& pass : kProgramPasses) passes += std::string(", ") + pass.name;
    throw InputError(std::string(e.what()) + " (or a pass" + passes + ")");
  }
  if (choices.size() != 1) throw InputError("--method " + method + ": one method or pass");
  return method_program_module(shaders, *choices[0].method, choices[0].params);
}

MaterialVariant program_material_variant(const std::string& kind_id, bool normal_map, bool textures, bool anisotropic,
                                         bool wang_tiles) {
  const MaterialKind& kind = kind_id.empty() ? default_material_kind() : find_material_kind(kind_id);
  if (kind.requires_normal_map && !normal_map)
    throw InputError("--material-kind " + kind.id + ": the kind requires a normal map; add --normal-map");
  if (wang_tiles && (kind.id != "normal-map-glints" || !normal_map))
    throw InputError("--wang-tiles: a normal-map-glints material's normal map only; allowed with --material-kind "
                     "normal-map-glints --normal-map");
  return {kind.code(), normal_map, textures, anisotropic, wang_tiles};
}

std::string program_source(const ProgramOptions& o) {
  DriverProfile profile = DriverProfile::Software;
  if (o.driver_profile == "hardware") profile = DriverProfile::Hardware;
  else if (o.driver_profile != "software")
    throw InputError("--driver-profile " + o.driver_profile + ": allowed: software, hardware");
  ProgramStage stage = ProgramStage::Fragment;
  if (o.stage == "vertex") stage = ProgramStage::Vertex;
  else if (o.stage != "fragment") throw InputError("--stage " + o.stage + ": allowed: fragment, vertex");
  ShaderLibrary shaders(profile);
  add_contract_sources(shaders);
  const std::string module = program_module(shaders, o.method, o.params);
  return forward_program_text(shaders, module, program_material_variant(o.material_kind, o.normal_map, o.textures, o.anisotropic, o.wang_tiles),
                              parse_light_counts(o.lights, "--lights"), stage);
}

}  // namespace glintlab
