#include "scene/materials/material_parser.hpp"

#include "scene/normal_maps/normal_map_parser.hpp"

namespace glintlab {

Material parse_material(TomlReader r, const std::filesystem::path& base_dir) {
  Material m;
  m.name = r.require_string("name");
  // The kind (its own keys and checks come from its declaration: src/scene/materials/<kind>.cpp).
  m.set_kind(find_material_kind(r.get_string("type", default_material_kind().id, material_kind_ids())));
  for (const MaterialParamDecl& p : m.kind->params)
    if (!p.derived)
      m.set_kind_param(p.key, static_cast<float>(r.get_number(p.key, p.default_value, p.min, p.max)));
  m.kind->parse_lobe(r, m);
  if (m.kind->requires_normal_map && !r.has("normal_map"))
    r.fail("normal_map", "is required by " + m.kind->id + " material '" + m.name +
                             "' (the map is its microsurface); allowed: a table { file = ... } or { generator = ... }");
  const bool has_f0 = r.has("f0");
  const bool has_metal = r.has("base_color") || r.has("metallic");
  if (has_f0 && has_metal) r.fail("f0", "cannot be combined with base_color/metallic; give one or the other");
  if (has_metal) {
    const glm::vec3 base = r.get_colour("base_color", glm::vec3(0.8f), 0.0, 1.0);
    const auto metallic = static_cast<float>(r.get_number("metallic", 0.0, 0.0, 1.0));
    m.f0 = glm::mix(glm::vec3(0.04f), base, metallic);
    m.diffuse = base * (1.0f - metallic);
    if (r.has("diffuse")) r.fail("diffuse", "cannot be combined with base_color/metallic (they set it)");
  } else {
    m.f0 = r.get_colour("f0", m.f0, 0.0, 1.0);
    m.diffuse = r.get_colour("diffuse", m.diffuse, 0.0, 1.0);
  }
  r.allow({"base_color", "metallic", "diffuse", "f0"});  // read in one branch or the other
  if (const toml::table* nm = r.get_table("normal_map"))
    m.normal_map = parse_normal_map(TomlReader(*nm, r.file(), "[[material]] '" + m.name + "' normal_map"), base_dir);
  if (m.normal_map && m.normal_map->wang && !m.is("normal-map-glints"))
    r.fail("normal_map", "has wang_tiles, which only a normal-map-glints material's map may have (material '" + m.name +
                             "' is " + m.kind->id + ")");
  m.normal_map_tiling = static_cast<float>(r.get_number("normal_map_tiling", 1.0, 1e-3, 1e5));
  if (m.kind->finish) m.kind->finish(r, m);
  r.finish();
  return m;
}

int material_named(const TomlReader& r, const std::string& key, const std::string& value,
                   const std::map<std::string, int>& materials) {
  auto it = materials.find(value);
  if (it == materials.end()) {
    std::string known;
    for (const auto& [k, v] : materials) known += (known.empty() ? "" : ", ") + k;
    r.fail(key, "value \"" + value + "\" names no [[material]]; defined: " + (known.empty() ? "none" : known));
  }
  return it->second;
}

}  // namespace glintlab
