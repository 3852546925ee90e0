#pragma once
// A forward program as the driver gets it, outside any scene: a shading module (a method's, the
// reference's, a pass's) in one material variant with some lights of each kind. What
// `glintlab program` prints and `glintlab shader-stats` compiles to SPIR-V (docs/shader-statistics.md).
#include <string>
#include <vector>

#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/renderer.hpp"

namespace glintlab {

/// Lights of each kind, in all_light_kinds() order.
using LightCounts = std::vector<int>;

/// The index ranges of a light buffer sorted by kind with `counts` lights of each kind.
LightRanges light_ranges_of(const LightCounts& counts);

/// Parses "quad=2,sphere=1" (kind=count, counts 0 .. 64; kinds not named have none). Throws
/// InputError naming `flag`, the entry and what is allowed.
LightCounts parse_light_counts(const std::string& text, const std::string& flag);
/// "quad=2,sphere=1": the kinds with lights, in registry order.
std::string light_counts_text(const LightCounts& counts);

enum class ProgramStage { Vertex, Fragment };

/// The expanded text of the forward program's stage for `module` (e.g. method_program_module's,
/// or kReferenceModule) in `material`'s variant with `lights`, in the library's driver profile,
/// with `extra` defines after the variant's.
std::string forward_program_text(const ShaderLibrary& shaders, const std::string& module, MaterialVariant material,
                                 const LightCounts& lights, ProgramStage stage, const ShaderDefines& extra = {});

struct LightKind;
/// The expanded text of an exported method (shaders/export/shade_pixel.frag; `glintlab export`):
/// the forward pass's shading of a pixel as the function glintlabShade, for one light of `light`'s
/// kind, in `material`'s variant and the library's driver profile.
std::string exported_program_text(const ShaderLibrary& shaders, const std::string& module, MaterialVariant material,
                                  const LightKind& light, const ShaderDefines& extra = {});

}  // namespace glintlab
