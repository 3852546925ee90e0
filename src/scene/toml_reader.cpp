#include "scene/toml_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace glintlab {

namespace {
std::string describe(const toml::node& node) {
  std::ostringstream s;
  if (node.is_string()) {
    s << '"' << node.as_string()->get() << '"';
  } else if (node.is_table()) {
    s << "a table";
  } else if (node.is_array()) {
    s << "an array of " << node.as_array()->size();
  } else {
    node.visit([&](const auto& v) {
      if constexpr (toml::is_floating_point<decltype(v)>) s << number_text(v.get());
      else if constexpr (toml::is_number<decltype(v)> || toml::is_boolean<decltype(v)>) s << v;
    });
  }
  return s.str();
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

std::string number_text(double value) {
  // The fewest digits that read back as the value: 1073741824, not 1.07374e+09; 360.0001, not 360.
  // A value that is a float (a declared default) reads back at float precision: 0.1, not
  // 0.10000000149011612.
  char text[40];
  if (value == std::trunc(value) && std::abs(value) < 1e15) {
    std::snprintf(text, sizeof text, "%.0f", value);
    return text;
  }
  const bool is_float = static_cast<double>(static_cast<float>(value)) == value;
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    const double back = std::strtod(text, nullptr);
    if (is_float ? static_cast<float>(back) == static_cast<float>(value) : back == value) break;
  }
  return text;
}

std::string range_text(double min, double max) { return number_text(min) + " .. " + number_text(max); }

TomlReader::TomlReader(const toml::table& table, std::string file, std::string context)
    : table_(table), file_(std::move(file)), context_(std::move(context)) {}

bool TomlReader::has(const std::string& key) const { return table_.contains(key); }

std::string TomlReader::where(const std::string& key) const {
  std::ostringstream s;
  s << file_;
  const toml::node* node = table_.get(key);
  const auto& src = node ? node->source() : table_.source();
  if (src.begin.line > 0) s << ':' << src.begin.line;
  s << ": " << context_;
  if (!key.empty()) s << (context_.empty() ? "" : " ") << "key '" << key << "'";
  return s.str();
}

void TomlReader::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key) + ": " + message);
}

const toml::node* TomlReader::lookup(const std::string& key) {
  used_.insert(key);
  return table_.get(key);
}

double TomlReader::as_number(const std::string& key, const toml::node& node, double min, double max) const {
  double v = 0;
  if (auto i = node.value_exact<int64_t>()) {
    v = static_cast<double>(*i);
  } else if (auto d = node.value_exact<double>()) {
    v = *d;
  } else {
    fail(key, "value " + describe(node) + " is not a number; allowed: " + range_text(min, max));
  }
  if (!std::isfinite(v) || v < min || v > max) {
    fail(key, "value " + number_text(v) + " is out of range; allowed: " + range_text(min, max));
  }
  return v;
}

std::string TomlReader::get_string(const std::string& key, const std::string& fallback,
                                   const std::vector<std::string>& allowed) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  if (!n->is_string())
    fail(key, "value " + describe(*n) + " is not a string" + (allowed.empty() ? "" : "; allowed: " + join(allowed)));
  std::string v = n->as_string()->get();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end())
    fail(key, "value \"" + v + "\" is not allowed; allowed: " + join(allowed));
  return v;
}

std::string TomlReader::require_string(const std::string& key, const std::vector<std::string>& allowed) {
  if (!has(key)) fail(key, "is required" + (allowed.empty() ? "" : "; allowed: " + join(allowed)));
  return get_string(key, "", allowed);
}

double TomlReader::get_number(const std::string& key, double fallback, double min, double max) {
  const toml::node* n = lookup(key);
  return n ? as_number(key, *n, min, max) : fallback;
}

double TomlReader::require_number(const std::string& key, double min, double max) {
  if (!has(key)) fail(key, "is required; allowed: " + range_text(min, max));
  return get_number(key, 0.0, min, max);
}

int TomlReader::get_int(const std::string& key, int fallback, int min, int max) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  auto i = n->value_exact<int64_t>();
  if (!i) fail(key, "value " + describe(*n) + " is not an integer; allowed: " + range_text(min, max));
  if (*i < min || *i > max)
    fail(key, "value " + std::to_string(*i) + " is out of range; allowed: " + range_text(min, max));
  return static_cast<int>(*i);
}

bool TomlReader::get_bool(const std::string& key, bool fallback) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  if (!n->is_boolean()) fail(key, "value " + describe(*n) + " is not a boolean; allowed: true, false");
  return n->as_boolean()->get();
}

glm::vec3 TomlReader::get_vec3(const std::string& key, glm::vec3 fallback) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3) fail(key, "value " + describe(*n) + " is not an array of 3 numbers");
  glm::vec3 v;
  for (int c = 0; c < 3; ++c) v[c] = static_cast<float>(as_number(key, *a->get(static_cast<std::size_t>(c)), -1e6, 1e6));
  return v;
}

glm::vec3 TomlReader::require_vec3(const std::string& key) {
  if (!has(key)) fail(key, "is required (an array of 3 numbers)");
  return get_vec3(key, glm::vec3(0.0f));
}

glm::vec3 TomlReader::get_colour(const std::string& key, glm::vec3 fallback, double min, double max) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  if (const toml::array* a = n->as_array()) {
    if (a->size() != 3) fail(key, "value " + describe(*n) + " is not a number or an array of 3 numbers");
    glm::vec3 v;
    for (int c = 0; c < 3; ++c) v[c] = static_cast<float>(as_number(key, *a->get(static_cast<std::size_t>(c)), min, max));
    return v;
  }
  return glm::vec3(static_cast<float>(as_number(key, *n, min, max)));
}

glm::vec2 TomlReader::get_vec2(const std::string& key, glm::vec2 fallback, double min, double max) {
  const toml::node* n = lookup(key);
  if (!n) return fallback;
  if (const toml::array* a = n->as_array()) {
    if (a->size() != 2) fail(key, "value " + describe(*n) + " is not a number or an array of 2 numbers");
    return {static_cast<float>(as_number(key, *a->get(0), min, max)),
            static_cast<float>(as_number(key, *a->get(1), min, max))};
  }
  return glm::vec2(static_cast<float>(as_number(key, *n, min, max)));
}

std::vector<glm::vec3> TomlReader::require_vec3_list(const std::string& key, std::size_t min_count) {
  const toml::node* n = lookup(key);
  if (!n) fail(key, "is required (an array of [x, y, z] points)");
  const toml::array* a = n->as_array();
  if (!a || a->size() < min_count)
    fail(key, "value " + describe(*n) + " is not an array of at least " + std::to_string(min_count) + " points");
  std::vector<glm::vec3> out;
  for (const auto& e : *a) {
    const toml::array* p = e.as_array();
    if (!p || p->size() != 3) fail(key, "element " + describe(e) + " is not an array of 3 numbers");
    glm::vec3 v;
    for (int c = 0; c < 3; ++c) v[c] = static_cast<float>(as_number(key, *p->get(static_cast<std::size_t>(c)), -1e6, 1e6));
    out.push_back(v);
  }
  return out;
}

const toml::table* TomlReader::get_table(const std::string& key) {
  const toml::node* n = lookup(key);
  if (!n) return nullptr;
  if (!n->is_table()) fail(key, "value " + describe(*n) + " is not a table");
  return n->as_table();
}

std::vector<const toml::table*> TomlReader::get_table_array(const std::string& key) {
  const toml::node* n = lookup(key);
  if (!n) return {};
  const toml::array* a = n->as_array();
  if (!a) fail(key, "value " + describe(*n) + " is not an array of tables (use [[" + key + "]])");
  std::vector<const toml::table*> out;
  for (const auto& e : *a) {
    if (!e.is_table()) fail(key, "element " + describe(e) + " is not a table");
    out.push_back(e.as_table());
  }
  return out;
}

void TomlReader::finish() const {
  for (const auto& [k, v] : table_) {
    const std::string key(k.str());
    if (!used_.contains(key)) {
      std::string known;
      for (const auto& u : used_) known += (known.empty() ? "" : ", ") + u;
      fail(key, "is not a known key; allowed here: " + known);
    }
  }
}

}  // namespace glintlab
