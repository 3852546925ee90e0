#pragma once
// GLSL generated from the C++ side, so that the shaders never restate a constant, a layout or the
// list of light or material kinds: generated/gpu_contract.glsl (src/core/gpu_contract.hpp's
// constants, the kinds' codes, the tables' units and constants and the methods' choices as
// defines), generated/gpu_structs.glsl (its std140 records), generated/material_params.glsl (each
// material kind's parameters), generated/materials/<kind>.glsl (a kind behind the material
// interface), generated/light_kinds.glsl (each kind's file and the dispatch of the light interface,
// shaders/lights/lights.glsl) and generated/shade_all_lights.glsl (the light loop's call per kind,
// shaders/lights/light_loop.glsl).
#include <string>
#include <utility>
#include <vector>

#include "gl/shader_library.hpp"

namespace glintlab {

/// (path, text) of every generated source.
std::vector<std::pair<std::string, std::string>> generated_shader_sources();

/// Adds the generated sources to a library (every library that compiles the shaders needs them;
/// Renderer does it for its own).
void add_contract_sources(ShaderLibrary& shaders);

/// The defines of generated/gpu_contract.glsl, (name, value) in order. Throws std::logic_error
/// if two of them have one name.
ShaderDefines contract_defines();

struct LightKind;
/// LIGHT_<ID>: the define of the kind's code in GLSL.
std::string light_code_name(const LightKind& kind);
/// LIGHT_<ID>_COUNT: the forward variant's define of how many lights of the kind the scene has;
/// the generated light dispatch and light loop compile only the kinds a scene has.
std::string light_count_define(const LightKind& kind);
/// LIGHT_<ID>_BUILT: defined by the forward variant of a module that builds lights of the kind
/// itself (MethodDescriptor::light_kinds_built), so that the kind is compiled without scene lights.
std::string light_built_define(const LightKind& kind);

struct MaterialKind;
/// The generated module of a material kind for the forward pass's $MATERIAL slot: the kind's
/// shaders/materials/<id>.glsl behind the material interface (materialSpecularCos, ...).
std::string material_kind_module(const MaterialKind& kind);
/// The $MATERIAL module of normal-map-glints materials in the path tracer's backends `path:<method>`:
/// the method's footprint NDF in the $METHOD slot behind the material interface
/// (shaders/materials/normal-map-glints-footprint.glsl).
inline constexpr const char* kFootprintNdfMaterialModule = "generated/materials/normal-map-glints-footprint.glsl";

}  // namespace glintlab
