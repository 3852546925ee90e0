#include "shading/method_list.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "core/error.hpp"
#include "shading/registry.hpp"

namespace glintlab {

namespace {

const char* const kAllowedEntries =
    "method ids separated by commas, 'all', or variants id{name=value,...} (see 'glintlab methods')";

/// `where`: what the message names first ("--methods 'a,b'").
[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

/// A value goes into file names: letters, digits and what numbers and choice names are made of.
bool file_safe(const std::string& value) {
  return std::all_of(value.begin(), value.end(),
                     [](unsigned char c) { return std::isalnum(c) || c == '.' || c == '_' || c == '+' || c == '-'; });
}

std::string parameter_names(const MethodDescriptor& m) {
  std::string names;
  for (const auto& p : m.params) names += (names.empty() ? "" : ", ") + p.name;
  return names.empty() ? "none" : names;
}

/// id{name=value,...}: the method, its settings checked against its parameters, and its names.
/// `origin`: as parse_method_variants'; `where`: what its messages name first.
MethodVariant parse_variant(const std::string& where, const std::string& entry, const std::string& origin) {
  const auto open = entry.find('{');
  const std::string id = entry.substr(0, open);
  if (id.empty()) fail(where, "no method before '{' in '" + entry + "'; allowed: " + kAllowedEntries);
  MethodVariant v;
  try {
    v.method = &find_method(id);
  } catch (const InputError& e) {
    fail(where, e.what());
  }
  v.name = v.file_name = id;
  if (open == std::string::npos) return v;
  if (entry.back() != '}')
    fail(where, "text after '}' in '" + entry + "'; allowed: " + id + "{name=value,...} then ',' or the end");
  const std::string inside = entry.substr(open + 1, entry.size() - open - 2);
  const std::string allowed = "; allowed: name=value of " + id + "'s parameters (" + parameter_names(*v.method) + ")";
  if (inside.empty()) fail(where, "nothing between the braces of '" + entry + "'" + allowed);
  std::map<std::string, std::string> settings;
  std::size_t start = 0;
  for (;;) {
    const auto comma = inside.find(',', start);
    const std::string setting = inside.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == setting.size())
      fail(where, "'" + setting + "' in '" + entry + "' is not name=value" + allowed);
    const std::string name = setting.substr(0, eq), value = setting.substr(eq + 1);
    if (!settings.emplace(name, value).second)
      fail(where, "parameter '" + name + "' is set twice in '" + entry + "'; allowed: each parameter once");
    v.settings.emplace_back(name, value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  // Unknown parameters and bad values, with the message --param gets, naming the variant.
  resolve_params(*v.method, settings, origin.empty() ? "--methods '" + entry + "':" : origin + ":");
  for (const auto& [name, value] : v.settings)
    if (!file_safe(value))  // " 1" is a number to std::stof
      fail(where,
           "value '" + value + "' of '" + name + "' in '" + entry +
               "' holds other characters than a number or a choice; allowed: " + v.method->find_param(name)->allowed());
  v.name = entry;
  for (const auto& [name, value] : v.settings) v.file_name += "." + name + "=" + value;
  return v;
}

}  // namespace

std::vector<std::string> split_outside_braces(const std::string& list, const std::string& where) {
  auto fail_at = [&](const std::string& what) { fail(where, what); };
  std::vector<std::string> entries(1);
  bool inside = false;
  for (const char c : list) {
    std::string& entry = entries.back();
    if (c == ',' && !inside) {
      entries.emplace_back();
      continue;
    }
    entry += c;
    if (c == '{' && inside) fail_at("braces inside braces in '" + entry + "'; allowed: id{name=value,...}");
    if (c == '}' && !inside) fail_at("a '}' without its '{' in '" + entry + "'; allowed: id{name=value,...}");
    if (c == '{' || c == '}') inside = c == '{';
  }
  if (inside) fail_at("a '{' without its '}' in '" + entries.back() + "'; allowed: id{name=value,...}");
  return entries;
}

std::vector<MethodVariant> parse_method_variants(const std::string& list, const std::string& origin) {
  const std::string where = origin.empty() ? "--methods '" + list + "'" : origin;
  std::vector<MethodVariant> variants;
  std::map<std::string, bool> names;  // name -> listed by 'all'
  const auto add = [&](MethodVariant v, bool by_all) {
    // Distinct names have distinct file names: a setting's name holds no '.' and its value no '='.
    if (const auto [it, added] = names.emplace(v.name, by_all); !added)
      fail(where, "'" + v.name + "' is listed twice" + (by_all || it->second ? " ('all' holds every method)" : "") +
                     "; allowed: each name once");
    variants.push_back(std::move(v));
  };
  for (const std::string& entry : split_outside_braces(list, where)) {
    if (entry.empty()) fail(where, std::string("an empty entry; allowed: ") + kAllowedEntries);
    if (entry == "all") {
      for (const auto& m : all_methods()) add({&m, {}, m.id, m.id}, true);
      continue;
    }
    add(parse_variant(where, entry, origin), false);
  }
  return variants;
}

std::vector<MethodChoice> resolve_methods(const std::string& methods, const std::vector<std::string>& params) {
  const std::vector<MethodVariant> variants = parse_method_variants(methods);
  std::vector<std::map<std::string, std::string>> overrides(variants.size());
  for (const auto& p : params) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param '" + p + "': expected name=value or method.name=value");
    std::string name = p.substr(0, eq);
    const std::string value = p.substr(eq + 1);
    std::string only;
    if (const auto dot = name.find('.'); dot != std::string::npos) {
      only = name.substr(0, dot);
      name = name.substr(dot + 1);
      find_method(only);  // unknown method ids are an error
    }
    bool used = false;
    for (std::size_t i = 0; i < variants.size(); ++i) {
      const auto& m = *variants[i].method;
      if ((!only.empty() && m.id != only) || (only.empty() && !m.find_param(name) && variants.size() > 1)) continue;
      overrides[i][name] = value;  // resolve_params reports unknown names and bad values
      used = true;
    }
    if (!used) {
      std::string known;
      std::set<std::string> listed;
      for (const auto& v : variants)
        if (listed.insert(v.method->id).second)
          for (const auto& q : v.method->params) known += (known.empty() ? "" : ", ") + v.method->id + "." + q.name;
      throw InputError("--param '" + p +
                       "': no selected method has this parameter; allowed: " + (known.empty() ? "none" : known));
    }
  }
  std::vector<MethodChoice> choices;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const MethodVariant& v = variants[i];
    resolve_params(*v.method, overrides[i]);  // --param's values are checked even where a variant sets them
    std::map<std::string, std::string> merged = overrides[i];
    for (const auto& [name, value] : v.settings) merged[name] = value;  // the variant's own settings win
    choices.push_back(
        {v.method, resolve_params(*v.method, merged, "--methods '" + v.name + "':"), v.name, v.file_name});
  }
  return choices;
}

}  // namespace glintlab
