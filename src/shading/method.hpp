#pragma once
// A shading method: one GLSL module (shaders/methods/<id>.glsl) plus this descriptor. The
// renderer only ever sees descriptors; it never names a method.
#include <map>
#include <string>
#include <vector>

namespace glintlab {

/// A parameter of a method; the module reads it as `param_<name>`, declared for it from this
/// declaration (shading/method_module.hpp): a `uniform float`, or for an enumeration (a parameter
/// with `choices`) a `uniform int` holding the choice's index. An enumeration takes a choice's name
/// (or its index), and min and max are then 0 and choices.size() - 1. GLSL compares it only with
/// the generated defines <NAME>_<CHOICE> (choice_define(); generated/gpu_contract.glsl), which
/// every shader sees, so that code shared by several methods can test a choice without naming one.
struct ParamDecl {
  std::string name;
  float default_value;
  float min;
  float max;
  std::string description;
  std::vector<std::string> choices = {};
  /// An enumeration that selects code rather than a value: the module sees `param_<name>` as a
  /// `const int` and each choice is its own program, so no driver pays for the code of the choices
  /// not taken (Mesa's llvmpipe runs both sides of every branch).
  bool compile_time = false;
  /// The precomputed tables each choice needs besides the method's own (indexed like `choices`;
  /// empty: none), made resident only when that choice is rendered.
  std::vector<std::vector<std::string>> choice_tables = {};
  /// A setting of the data the renderer prepares for the method (deng2022's precompute), read on
  /// the host and never by the module: no uniform is generated for it.
  bool host_only = false;
  /// A count (a rank, a resolution): a value with a fraction is refused, never rounded.
  bool integer = false;
  /// A host-only count the module is also compiled for (deng2022's rank and angular grid): it sees
  /// `const int param_<name>` holding the value, each value its own program, so that loops over it
  /// unroll and divisions by it fold (a GPU's shifts instead of integer divisions). Needs
  /// host_only and integer.
  bool specialises = false;

  [[nodiscard]] bool is_enumeration() const { return !choices.empty(); }
  /// "0 .. 1", or "a|b|c" for an enumeration.
  [[nodiscard]] std::string allowed() const;
  /// The default as a user writes it: the number, or the choice's name.
  [[nodiscard]] std::string default_text() const;
};

struct MethodDescriptor {
  std::string id;        ///< also the module's file name: shaders/methods/<id>.glsl
  std::string title;
  std::string citation;  ///< the paper (or "baseline")
  std::string summary;   ///< one paragraph, shown by `glintlab methods`
  std::vector<ParamDecl> params;
  /// Ids of the precomputed tables the module reads (src/tables/registry.cpp): made
  /// resident and bound before the renderer draws with it.
  std::vector<std::string> tables;
  /// Ids of the other resources the module reads (src/render/resources/resource.hpp; e.g.
  /// "prefiltered-ndf"): made for the scene and the parameters' values, resident and bound before
  /// the renderer draws with it.
  std::vector<std::string> resources = {};
  /// Ids of the light kinds the module builds lights of itself (podee's widened quad): compiled
  /// into its programs whatever kinds the scene has (src/render/renderer.cpp, forward_variant).
  std::vector<std::string> light_kinds_built = {};
  /// Ids of the material kinds the module has code of its own for (`#if MATERIAL_KIND ==
  /// MATERIAL_KIND_<ID>`: deliot2023's binomial-glints); every other kind it shades through the
  /// material interface (its smooth lobe, as conventional). Empty: it treats every kind alike.
  std::vector<std::string> material_kinds = {};
  /// Whether its module gives a normal-map-glints material's footprint NDF to the path tracer
  /// (compiled with METHOD_AS_FOOTPRINT_NDF: shaders/materials/normal-map-glints-footprint.glsl),
  /// which then renders the method's appearance offline: the reference backend `path:<id>`.
  bool path_footprint_ndf = false;

  [[nodiscard]] std::string module_path() const { return "methods/" + id + ".glsl"; }
  [[nodiscard]] const ParamDecl* find_param(const std::string& name) const;
};

/// Parameter values by name, every declared parameter present (an enumeration's as its choice's
/// index, a whole number).
using ParamValues = std::map<std::string, float>;

/// The GLSL define of an enumeration's choice, <NAME>_<CHOICE> in upper snake case:
/// ("area_lights", "representative-point") -> "AREA_LIGHTS_REPRESENTATIVE_POINT",
/// ("subdivision", "2x2") -> "SUBDIVISION_2X2". Its value is the choice's index.
std::string choice_define(const std::string& param, const std::string& choice);

/// The tables rendering `method` with `values` needs: its own, then those of the chosen choices.
std::vector<std::string> required_tables(const MethodDescriptor& method, const ParamValues& values);
/// Every table some choice of `method` may need (for listings and for making tables resident up front).
std::vector<std::string> all_tables_of(const MethodDescriptor& method);

/// Defaults overridden by `overrides` ("name=value" strings already split). Throws InputError for
/// an unknown parameter (listing the method's parameters) or a value out of range; the message
/// starts with `origin` and the name=value (a --methods variant passes its own).
ParamValues resolve_params(const MethodDescriptor& method, const std::map<std::string, std::string>& overrides,
                           const std::string& origin = "--param");

}  // namespace glintlab
