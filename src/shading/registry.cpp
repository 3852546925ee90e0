#include "shading/registry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace glintlab {

MethodDescriptor conventional_method();
MethodDescriptor toksvig_method();
MethodDescriptor vlachos_method();
MethodDescriptor kaplanyan_beckmann_method();
MethodDescriptor kaplanyan_rect_method();
MethodDescriptor kaplanyan_ggx_method();
MethodDescriptor tokuyoshi_method();
MethodDescriptor lean_method();
MethodDescriptor podee_method();
MethodDescriptor chermain2020_method();
MethodDescriptor chermain2021_method();

const std::vector<MethodDescriptor>& all_methods() {
  static const std::vector<MethodDescriptor> methods = {
      conventional_method(),       toksvig_method(),     vlachos_method(),   kaplanyan_beckmann_method(),
      kaplanyan_rect_method(),     kaplanyan_ggx_method(), tokuyoshi_method(), lean_method(),
      podee_method(),              chermain2020_method(), chermain2021_method(),
  };
  return methods;
}

std::string ParamDecl::allowed() const {
  std::ostringstream out;
  if (choices.empty()) {
    out << min << " .. " << max;
  } else {
    for (std::size_t i = 0; i < choices.size(); ++i) out << (i ? "|" : "") << choices[i];
  }
  return out.str();
}

std::string ParamDecl::default_text() const {
  const auto index = static_cast<std::size_t>(default_value);
  if (!choices.empty() && index < choices.size()) return choices[index];
  std::ostringstream out;
  out << default_value;
  return out.str();
}

const ParamDecl* MethodDescriptor::find_param(const std::string& name) const {
  for (const auto& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

const MethodDescriptor& find_method(const std::string& id) {
  for (const auto& m : all_methods())
    if (m.id == id) return m;
  std::string known;
  for (const auto& m : all_methods()) known += (known.empty() ? "" : ", ") + m.id;
  throw InputError("unknown method '" + id + "'; allowed: " + known + " (see 'glintlab methods')");
}

std::vector<const MethodDescriptor*> parse_method_list(const std::string& list) {
  std::vector<const MethodDescriptor*> out;
  if (list == "all") {
    for (const auto& m : all_methods()) out.push_back(&m);
    return out;
  }
  std::stringstream s(list);
  std::string id;
  while (std::getline(s, id, ',')) {
    if (id.empty()) throw InputError("--methods '" + list + "': empty method name; give ids separated by commas, or 'all'");
    const MethodDescriptor* m = &find_method(id);
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  }
  if (out.empty()) throw InputError("--methods: no method given; give ids separated by commas, or 'all'");
  return out;
}

ParamValues resolve_params(const MethodDescriptor& method, const std::map<std::string, std::string>& overrides) {
  ParamValues values;
  for (const auto& p : method.params) values[p.name] = p.default_value;
  for (const auto& [name, text] : overrides) {
    const ParamDecl* p = method.find_param(name);
    if (!p) {
      std::string known;
      for (const auto& q : method.params) known += (known.empty() ? "" : ", ") + q.name;
      throw InputError("--param " + name + "=" + text + ": method '" + method.id + "' has no parameter '" + name +
                       "'; allowed: " + (known.empty() ? "none" : known));
    }
    if (const auto it = std::find(p->choices.begin(), p->choices.end(), text); it != p->choices.end()) {
      values[name] = static_cast<float>(it - p->choices.begin());
      continue;
    }
    std::size_t used = 0;
    float v = 0;
    try {
      v = std::stof(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    const std::string what = p->choices.empty() ? "not a number" : "not a choice";
    if (used != text.size() || text.empty() || !std::isfinite(v))
      throw InputError("--param " + name + "=" + text + ": " + what + "; allowed: " + p->allowed());
    if (v < p->min || v > p->max || (!p->choices.empty() && v != std::floor(v)))
      throw InputError("--param " + name + "=" + text + ": out of range for '" + method.id + "'; allowed: " + p->allowed());
    values[name] = v;
  }
  return values;
}

}  // namespace glintlab
