#pragma once
// `glintlab program`: one forward program's GLSL as the driver gets it, for reading what a method
// compiles to, for engines that lift a method, and for `glintlab shader-stats`.
#include <string>
#include <vector>

#include "gl/shader_library.hpp"
#include "render/renderer.hpp"

namespace glintlab {

struct ProgramOptions {
  std::string method = "conventional";  ///< a method or variant (--methods syntax), or a pass (kProgramPasses)
  std::vector<std::string> params;      ///< --param, as the rendering commands take it
  std::string material_kind;            ///< empty: the default kind
  bool normal_map = false;
  bool textures = false;
  bool anisotropic = false;
  bool wang_tiles = false;              ///< the normal map is a surface of Wang tiles (normal-map-glints only)
  std::string lights = "point=1";       ///< parse_light_counts
  std::string stage = "fragment";       ///< fragment or vertex
  std::string driver_profile = "software";
};

/// The passes `--method` takes besides methods: the raster references and the unshaded floor.
struct ProgramPass {
  const char* name;
  const char* module;
};
inline constexpr ProgramPass kProgramPasses[] = {{"reference", kReferenceModule},
                                                 {"reference-realisation", kRealisationReferenceModule},
                                                 {"reference-facets", kFacetsReferenceModule},
                                                 {"unshaded", "passes/unshaded.glsl"}};

/// The module, in `shaders` (a method's generated module is added to it), that `method` names:
/// a method or variant with `params`, or one of kProgramPasses. Throws InputError as
/// resolve_methods does, naming the passes too.
std::string program_module(ShaderLibrary& shaders, const std::string& method, const std::vector<std::string>& params);

/// The material variant of --material-kind/--normal-map/--textures/--anisotropic/--wang-tiles; throws
/// InputError for an unknown kind, a kind that requires a normal map without one, or Wang tiles on a
/// kind other than normal-map-glints (the scene file refuses them there too).
MaterialVariant program_material_variant(const std::string& kind, bool normal_map, bool textures,
                                         bool anisotropic = false, bool wang_tiles = false);

/// The program's text; throws InputError naming the option for a bad value.
std::string program_source(const ProgramOptions& options);

}  // namespace glintlab
