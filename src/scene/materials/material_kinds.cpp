// The registry of material kinds: every kind registered by its own file, ordered by key (the
// order is the kinds' GPU codes).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "core/error.hpp"
#include "scene/materials/material.hpp"
#include "scene/materials/material_kind.hpp"

namespace glintlab {

namespace {

std::vector<MaterialKindRegistration>& registrations() {
  static std::vector<MaterialKindRegistration> list;  // function-local: filled during static initialisation
  return list;
}

bool registry_read = false;

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

void check_declaration(const MaterialKind& k, const char* file) {
  const std::string where =
      "material kind '" + k.id + "' (" + std::filesystem::path(file).filename().string() + ")";
  const auto id_char = [](char c) {
    return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '-';
  };
  if (k.id.empty() || !std::all_of(k.id.begin(), k.id.end(), id_char) || k.id.front() == '-')
    throw std::logic_error(where + ": a material kind id is one or more of a-z, 0-9 and '-', not starting with '-'");
  if (!k.parse_lobe) throw std::logic_error(where + ": parse_lobe is not set");
  if (k.params.size() > static_cast<std::size_t>(kMaxMaterialKindParams))
    throw std::logic_error(where + ": " + std::to_string(k.params.size()) + " parameters; MaterialGpu::kind_params holds " +
                           std::to_string(kMaxMaterialKindParams));
  for (std::size_t i = 0; i < k.params.size(); ++i) {
    const MaterialParamDecl& p = k.params[i];
    if (!is_identifier(p.key)) throw std::logic_error(where + ": parameter key '" + p.key + "' is not an identifier");
    for (std::size_t j = 0; j < i; ++j)
      if (k.params[j].key == p.key) throw std::logic_error(where + ": parameter '" + p.key + "' is declared twice");
    if (!(p.min <= p.default_value && p.default_value <= p.max))
      throw std::logic_error(where + ": parameter '" + p.key + "' has its default outside its range");
  }
}

std::string camel_case(const std::string& id) {
  std::string out;
  bool upper = false;
  for (char c : id) {
    if (c == '-') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out;
}

}  // namespace

bool register_material_kind(const MaterialKindRegistration& registration) {
  if (registry_read)
    throw std::logic_error(std::string("material kind registered after the registry was read (") +
                           registration.source_file + ")");
  registrations().push_back(registration);
  return true;
}

const std::vector<MaterialKind>& all_material_kinds() {
  static const std::vector<MaterialKind> kinds = [] {
    registry_read = true;
    std::vector<MaterialKindRegistration> sorted = registrations();
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    std::vector<MaterialKind> list;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      MaterialKind k = sorted[i].make();
      check_declaration(k, sorted[i].source_file);
      for (std::size_t j = 0; j < i; ++j) {
        if (sorted[j].key == sorted[i].key || list[j].id == k.id)
          throw std::logic_error("material kinds '" + list[j].id + "' (" + sorted[j].source_file + ") and '" + k.id +
                                 "' (" + sorted[i].source_file + ") share an id or a registration key");
      }
      list.push_back(std::move(k));
    }
    return list;
  }();
  return kinds;
}

int MaterialKind::code() const { return static_cast<int>(this - all_material_kinds().data()); }

std::string MaterialKind::glsl_prefix() const { return camel_case(id); }

std::string MaterialKind::define() const {
  std::string name = "MATERIAL_KIND_";
  for (char c : id) name += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

int MaterialKind::param_index(std::string_view key) const {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].key == key) return static_cast<int>(i);
  throw std::logic_error("material kind '" + id + "' declares no parameter '" + std::string(key) + "'");
}

std::vector<std::string> material_kind_ids() {
  std::vector<std::string> ids;
  for (const auto& k : all_material_kinds()) ids.push_back(k.id);
  return ids;
}

const MaterialKind& find_material_kind(const std::string& id) {
  const auto& kinds = all_material_kinds();
  auto it = std::find_if(kinds.begin(), kinds.end(), [&](const MaterialKind& k) { return k.id == id; });
  if (it != kinds.end()) return *it;
  std::string known;
  for (const auto& k : kinds) known += (known.empty() ? "" : ", ") + k.id;
  throw InputError("unknown material type \"" + id + "\"; registered: " + known);
}

const MaterialKind& default_material_kind() { return find_material_kind("microfacet"); }

void hash_material_kind(Hasher& hasher, const Material& material) {
  hasher.text(material.kind->id);
  for (std::size_t i = 0; i < material.kind->params.size(); ++i) hasher.value(material.kind_params[i]);
}

}  // namespace glintlab
