#include "shading/registry.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "shading/method_module.hpp"

namespace glintlab {

namespace {

std::vector<MethodRegistration>& registrations() {
  static std::vector<MethodRegistration> list;  // function-local: filled during static initialisation
  return list;
}

bool registry_read = false;  // set by all_methods(); its vector must not change once handed out

std::string file_name(const char* path) { return std::filesystem::path(path).filename().string(); }

bool lower_alnum(char c) {
  return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c));
}

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), glsl_identifier_char);
}

/// The id names the module's file and is the key of `--param id.name`; a parameter becomes the
/// GLSL uniform `param_<name>`.
void check_declaration(const MethodDescriptor& m, const char* file) {
  const std::string where = "method '" + m.id + "' (" + file_name(file) + ")";
  const auto id_char = [](char c) { return lower_alnum(c) || c == '-' || c == '_'; };
  if (m.id.empty() || !std::all_of(m.id.begin(), m.id.end(), id_char))
    throw std::logic_error(where + ": a method id is one or more of a-z, 0-9, '-' and '_'");
  for (std::size_t i = 0; i < m.params.size(); ++i) {
    const ParamDecl& p = m.params[i];
    if (!is_identifier(p.name))
      throw std::logic_error(where + ": parameter name '" + p.name +
                             "' is not a GLSL identifier ([A-Za-z_][A-Za-z0-9_]*)");
    for (std::size_t j = 0; j < i; ++j)
      if (m.params[j].name == p.name) throw std::logic_error(where + ": parameter '" + p.name + "' is declared twice");
    if (!(p.min <= p.default_value && p.default_value <= p.max))
      throw std::logic_error(where + ": parameter '" + p.name + "' has its default outside " + p.allowed());
    if (p.compile_time && p.choices.empty())
      throw std::logic_error(where + ": parameter '" + p.name + "' is compile_time but has no choices");
    if (p.specialises && !(p.host_only && p.integer && p.choices.empty()))
      throw std::logic_error(where + ": parameter '" + p.name + "' specialises the module but is not a host-only "
                             "integer");
    if (!p.choice_tables.empty() && p.choice_tables.size() != p.choices.size())
      throw std::logic_error(where + ": parameter '" + p.name + "' has " + std::to_string(p.choice_tables.size()) +
                             " choice_tables for " + std::to_string(p.choices.size()) + " choices");
    for (std::size_t c = 0; c < p.choices.size(); ++c) {
      const std::string& choice = p.choices[c];
      if (choice.empty() || !std::all_of(choice.begin(), choice.end(), id_char))
        throw std::logic_error(where + ": parameter '" + p.name + "' has the choice '" + choice +
                               "'; a choice is one or more of a-z, 0-9, '-' and '_'");
      for (std::size_t d = 0; d < c; ++d)
        if (choice_define(p.name, p.choices[d]) == choice_define(p.name, choice))
          throw std::logic_error(where + ": parameter '" + p.name + "' has the choices '" + p.choices[d] + "' and '" +
                                 choice + "', which are one GLSL define, " + choice_define(p.name, choice));
    }
  }
}

/// An enumeration's name is one meaning in GLSL (its defines <NAME>_<CHOICE> are shared by every
/// method), so every method that declares a parameter of that name declares the same choices;
/// and no two enumerations' choices make the same define. Host-only parameters never reach GLSL.
void check_enumerations_agree(const std::vector<MethodDescriptor>& methods,
                              const std::vector<MethodRegistration>& registrations) {
  struct Seen {
    const ParamDecl* param;
    std::size_t method;
  };
  std::vector<Seen> seen;
  std::map<std::string, Seen> defines;  // choice define -> the enumeration that makes it
  const auto where = [&](std::size_t m) {
    return "'" + methods[m].id + "' (" + file_name(registrations[m].source_file) + ")";
  };
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (const ParamDecl& p : methods[m].params) {
      if (p.host_only) continue;
      for (const Seen& s : seen) {
        if (s.param->name != p.name || (!p.is_enumeration() && !s.param->is_enumeration())) continue;
        if (s.param->choices != p.choices)
          throw std::logic_error("methods " + where(s.method) + " and " + where(m) + " both declare the parameter '" +
                                 p.name + "' but with other choices (" + s.param->allowed() + " and " + p.allowed() +
                                 "); an enumeration's name has one set of choices in every method (its GLSL "
                                 "defines are shared): use the same choices or another name");
      }
      seen.push_back({&p, m});
      for (const std::string& choice : p.choices) {
        const std::string define = choice_define(p.name, choice);
        const auto [it, added] = defines.try_emplace(define, Seen{&p, m});
        if (!added && it->second.param->name != p.name)
          throw std::logic_error("the choice '" + choice + "' of parameter '" + p.name + "' of method " + where(m) +
                                 " and a choice of parameter '" + it->second.param->name + "' of method " +
                                 where(it->second.method) + " are both the GLSL define " + define +
                                 "; rename one of them");
      }
    }
}

}  // namespace

bool register_method(const MethodRegistration& registration) {
  if (registry_read)
    throw std::logic_error(std::string("method registered by ") + file_name(registration.source_file) +
                           " after the registry was read; register at namespace scope with GLINTLAB_REGISTER_METHOD");
  registrations().push_back(registration);
  return true;
}

std::vector<MethodDescriptor> ordered_methods(const std::vector<MethodRegistration>& registrations) {
  std::vector<MethodRegistration> sorted = registrations;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.listing_key < b.listing_key; });
  std::vector<MethodDescriptor> methods;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    methods.push_back(sorted[i].make());
    const MethodDescriptor& m = methods.back();
    check_declaration(m, sorted[i].source_file);
    for (std::size_t j = 0; j < i; ++j) {
      const std::string both = file_name(sorted[j].source_file) + " and " + file_name(sorted[i].source_file);
      if (methods[j].id == m.id) throw std::logic_error("method id '" + m.id + "' is registered twice, by " + both);
      if (sorted[j].listing_key == sorted[i].listing_key)
        throw std::logic_error("methods '" + methods[j].id + "' and '" + m.id + "' share the listing key " +
                               std::to_string(sorted[i].listing_key) + " (" + both + "); give each its own");
    }
  }
  check_enumerations_agree(methods, sorted);
  return methods;
}

std::vector<std::pair<std::string, std::string>> enumeration_defines(const std::vector<MethodDescriptor>& methods) {
  std::vector<std::pair<std::string, std::string>> defines;
  std::set<std::string> done;  // parameter names (ordered_methods checked that they agree)
  for (const MethodDescriptor& m : methods)
    for (const ParamDecl& p : m.params) {
      if (p.host_only || !p.is_enumeration() || !done.insert(p.name).second) continue;
      for (std::size_t c = 0; c < p.choices.size(); ++c)
        defines.emplace_back(choice_define(p.name, p.choices[c]), std::to_string(c));
    }
  return defines;
}

const std::vector<MethodDescriptor>& all_methods() {
  static const std::vector<MethodDescriptor> methods = [] {
    registry_read = true;
    return ordered_methods(registrations());
  }();
  return methods;
}

std::string choice_define(const std::string& param, const std::string& choice) {
  std::string define;
  for (const char c : param + "_" + choice) {
    const auto u = static_cast<unsigned char>(c);
    define += std::isalnum(u) ? static_cast<char>(std::toupper(u)) : '_';
  }
  return define;
}

std::string ParamDecl::allowed() const {
  std::ostringstream out;
  if (choices.empty()) {
    out << (integer ? "an integer " : "") << min << " .. " << max;
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

namespace {
void add_unique(std::vector<std::string>& list, const std::string& id) {
  if (std::find(list.begin(), list.end(), id) == list.end()) list.push_back(id);
}
}  // namespace

std::vector<std::string> required_tables(const MethodDescriptor& method, const ParamValues& values) {
  std::vector<std::string> tables = method.tables;
  for (const ParamDecl& p : method.params) {
    const auto it = values.find(p.name);
    if (p.choice_tables.empty() || it == values.end()) continue;
    const auto choice = static_cast<std::size_t>(it->second);
    if (choice < p.choice_tables.size())
      for (const std::string& id : p.choice_tables[choice]) add_unique(tables, id);
  }
  return tables;
}

std::vector<std::string> all_tables_of(const MethodDescriptor& method) {
  std::vector<std::string> tables = method.tables;
  for (const ParamDecl& p : method.params)
    for (const auto& ids : p.choice_tables)
      for (const std::string& id : ids) add_unique(tables, id);
  return tables;
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

ParamValues resolve_params(const MethodDescriptor& method, const std::map<std::string, std::string>& overrides,
                           const std::string& origin) {
  ParamValues values;
  for (const auto& p : method.params) values[p.name] = p.default_value;
  for (const auto& [name, text] : overrides) {
    const ParamDecl* p = method.find_param(name);
    if (!p) {
      std::string known;
      for (const auto& q : method.params) known += (known.empty() ? "" : ", ") + q.name;
      throw InputError(origin + " " + name + "=" + text + ": method '" + method.id + "' has no parameter '" + name +
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
      throw InputError(origin + " " + name + "=" + text + ": " + what + "; allowed: " + p->allowed());
    if (p->integer && v != std::floor(v))
      throw InputError(origin + " " + name + "=" + text + ": not an integer; allowed: " + p->allowed());
    if (v < p->min || v > p->max || (!p->choices.empty() && v != std::floor(v)))
      throw InputError(origin + " " + name + "=" + text + ": out of range for '" + method.id +
                       "'; allowed: " + p->allowed());
    values[name] = v;
  }
  return values;
}

}  // namespace glintlab
