#pragma once
// A method's parameter uniforms, generated from its descriptor: the forward program includes
// generated/methods/<id>.glsl, which declares each ParamDecl's `param_<name>` (`uniform float`, or
// `uniform int` for an enumeration) and then includes the module, shaders/methods/<id>.glsl.
// Modules never declare them.
#include <cctype>
#include <string>

#include "shading/method.hpp"

namespace glintlab {

/// A character of a GLSL identifier (and of a parameter's name, which becomes one: param_<name>).
inline bool glsl_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// "generated/methods/<id>.glsl": the path the generated source is known by in the shader library;
/// with compile-time parameters, "<id>.<name>-<choice>...glsl", one per combination of their values
/// (and "<name>-<value>" for specialising ones).
std::string generated_module_path(const MethodDescriptor& method, const ParamValues& values = {});
/// The registered method whose generated module is at `path`, or nullptr (the reference's and
/// other passes' modules).
const MethodDescriptor* method_of_generated_module(const std::string& path);

/// The index of the choice a compile-time parameter takes in `values` (its default if absent).
std::size_t compile_time_choice(const ParamDecl& param, const ParamValues& values);
/// The value a specialising parameter (ParamDecl::specialises) takes in `values` (its default if absent).
int specialised_value(const ParamDecl& param, const ParamValues& values);

/// The generated source: one `uniform float param_<name>;` per declared parameter (`uniform int`
/// for an enumeration, the choice's index), then
/// `#include` of the module. `module_source` is the module's own text (not its includes), checked
/// first; throws RuntimeFailure naming the method, the parameter and the module's file when the
/// module never reads a declared parameter (whatever the optimiser keeps of it in a variant),
/// reads a `param_` identifier its descriptor does not declare, or declares one itself.
/// Compile-time parameters (ParamDecl::compile_time) become `const int param_<name>` of their
/// choice's index in `values` (the default where absent); specialising ones (ParamDecl::specialises)
/// `const int param_<name>` of their value.
std::string generated_module_source(const MethodDescriptor& method, const std::string& module_source,
                                    const ParamValues& values = {});

}  // namespace glintlab
