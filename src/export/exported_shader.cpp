#include "export/exported_shader.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"
#include "gl/shader_library.hpp"
#include "render/program_text.hpp"
#include "render/renderer.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"
#include "tables/registry.hpp"

namespace glintlab {

namespace {

// A GLSL float literal that reads back as `value`.
std::string float_literal(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string s = text;
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

// The method's uniform parameters as constants of the chosen values (the export is one variant),
// #line directives dropped (they number files the reader does not have).
std::string specialise(const std::string& text, const MethodChoice& m) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string line;
  int replaced = 0, expected = 0;
  for (const ParamDecl& p : m.method->params)
    if (!p.host_only && !p.compile_time) ++expected;
  while (std::getline(in, line)) {
    if (line.starts_with("#line ")) continue;
    bool done = false;
    for (const ParamDecl& p : m.method->params) {
      if (p.host_only || p.compile_time) continue;
      const std::string name = "param_" + p.name;
      const float value = m.params.count(p.name) ? m.params.at(p.name) : p.default_value;
      if (line == "uniform float " + name + ";") {
        out << "const float " << name << " = " << float_literal(value) << ";  // --param " << p.name << "\n";
        done = true;
      } else if (line == "uniform int " + name + ";") {
        const int index = static_cast<int>(std::lround(value));
        out << "const int " << name << " = " << index << ";  // " << choice_define(p.name, p.choices.at(index)) << "\n";
        done = true;
      }
    }
    if (done) ++replaced;
    else out << line << "\n";
  }
  if (replaced != expected)
    throw std::logic_error("export: " + std::to_string(replaced) + " of the " + std::to_string(expected) +
                           " parameter uniforms of '" + m.method->id + "' found in its program");
  return out.str();
}

}  // namespace

ExportedShader export_shader(const MethodChoice& method, const MaterialVariant& material, const LightKind& light,
                             DriverProfile profile) {
  ShaderLibrary shaders(profile);
  add_contract_sources(shaders);
  const std::string module = method_program_module(shaders, *method.method, method.params);
  ExportedShader e;
  e.glsl = "// Exported by `glintlab export` (docs/export.md): method " + method.display_name() + ", light kind " +
           light.id + ". Self-contained: the README beside it says how to bind its blocks and tables.\n" +
           specialise(exported_program_text(shaders, module, material, light), method);
  // #version must come first: the banner goes after it.
  const auto version = e.glsl.find("#version");
  if (version != std::string::npos) {
    const auto end = e.glsl.find('\n', version);
    const std::string directive = e.glsl.substr(version, end - version + 1);
    e.glsl.erase(version, end - version + 1);
    e.glsl.insert(0, directive);
  }
  // Every table the program declares (the method's, the material interface's, the lights'):
  // the caller keeps those its compiled code samples.
  for (const Table& t : all_tables())
    if (e.glsl.find(" " + t.sampler + ";") != std::string::npos) e.tables.push_back({t.source.id, t.sampler, t.unit});
  e.resources = method.method->resources;
  return e;
}

}  // namespace glintlab
