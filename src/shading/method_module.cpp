#include "shading/method_module.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "shading/registry.hpp"

namespace glintlab {

namespace {

constexpr const char* kParamPrefix = "param_";

/// The text with // and /* */ comments blanked, so that a parameter named only in a comment does
/// not count as read.
std::string without_comments(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      const std::size_t end = out.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (; i < stop; ++i)
        if (out[i] != '\n') out[i] = ' ';
      --i;
    }
  }
  return out;
}

struct ParamUses {
  std::set<std::string> read;      ///< names of every `param_<name>` in the text
  std::set<std::string> declared;  ///< names the text declares itself (`uniform <type> param_<name>`)
};

ParamUses param_uses(const std::string& source) {
  const std::string text = without_comments(source);
  ParamUses uses;
  std::string previous[2];  // the two identifiers before the current one
  for (std::size_t i = 0; i < text.size();) {
    if (!glsl_identifier_char(text[i])) {
      if (!std::isspace(static_cast<unsigned char>(text[i]))) previous[0] = previous[1] = "";
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && glsl_identifier_char(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    if (word.starts_with(kParamPrefix) && word.size() > std::string(kParamPrefix).size()) {
      const std::string name = word.substr(std::string(kParamPrefix).size());
      uses.read.insert(name);
      if (previous[0] == "uniform") uses.declared.insert(name);
    }
    previous[0] = previous[1];
    previous[1] = word;
    i = end;
  }
  return uses;
}

}  // namespace

std::string generated_module_path(const MethodDescriptor& method, const ParamValues& values) {
  std::string path = "generated/methods/" + method.id;
  for (const ParamDecl& p : method.params)
    if (p.compile_time)
      path += "." + p.name + "-" + p.choices.at(compile_time_choice(p, values));
    else if (p.specialises)
      path += "." + p.name + "-" + std::to_string(specialised_value(p, values));
  return path + ".glsl";
}

const MethodDescriptor* method_of_generated_module(const std::string& path) {
  const std::string prefix = "generated/methods/";
  if (!path.starts_with(prefix)) return nullptr;
  const std::string id = path.substr(prefix.size(), path.find('.', prefix.size()) - prefix.size());
  for (const MethodDescriptor& m : all_methods())
    if (m.id == id) return &m;
  return nullptr;
}

std::size_t compile_time_choice(const ParamDecl& param, const ParamValues& values) {
  const auto it = values.find(param.name);
  const float value = it == values.end() ? param.default_value : it->second;
  return std::min(static_cast<std::size_t>(std::max(value, 0.0f)), param.choices.size() - 1);
}

int specialised_value(const ParamDecl& param, const ParamValues& values) {
  const auto it = values.find(param.name);
  return static_cast<int>(std::lround(it == values.end() ? param.default_value : it->second));
}

std::string generated_module_source(const MethodDescriptor& method, const std::string& module_source,
                                    const ParamValues& values) {
  const std::string where = "method '" + method.id + "': shaders/" + method.module_path();
  const ParamUses uses = param_uses(module_source);
  if (!uses.declared.empty())
    throw RuntimeFailure(where + " declares the uniform param_" + *uses.declared.begin() +
                         " itself; parameter uniforms are generated from the descriptor's ParamDecls: remove the "
                         "declaration");
  for (const ParamDecl& p : method.params)
    if (p.host_only && !p.specialises && uses.read.contains(p.name))
      throw RuntimeFailure(where + " reads param_" + p.name + ", a host-only parameter (ParamDecl::host_only): the "
                           "module cannot see it");
    else if ((!p.host_only || p.specialises) && !uses.read.contains(p.name))
      throw RuntimeFailure(where + " never reads parameter '" + p.name + "' (param_" + p.name +
                           ") that its descriptor declares; use it in the module or remove the declaration");
  for (const std::string& name : uses.read)
    if (!method.find_param(name)) {
      std::string known;
      for (const ParamDecl& p : method.params) known += (known.empty() ? "" : ", ") + p.name;
      throw RuntimeFailure(where + " reads param_" + name + ", but its descriptor declares no parameter '" + name +
                           "' (declared: " + (known.empty() ? "none" : known) + ")");
    }

  std::string out = "// Generated from the descriptor of method '" + method.id +
                    "' (shading/method_module.hpp): its parameters, then its module.\n";
  for (const ParamDecl& p : method.params) {
    const std::string name = kParamPrefix + p.name;
    if (p.specialises) {
      out += "const int " + name + " = " + std::to_string(specialised_value(p, values)) + ";\n";
      continue;
    }
    if (p.host_only) continue;
    if (p.compile_time) {
      const std::size_t choice = compile_time_choice(p, values);
      out += "const int " + name + " = " + std::to_string(choice) + ";  // " +
             choice_define(p.name, p.choices[choice]) + "\n";
    } else {
      out += std::string(p.is_enumeration() ? "uniform int " : "uniform float ") + name + ";\n";
    }
  }
  return out + "#include \"" + method.module_path() + "\"\n";
}

}  // namespace glintlab
