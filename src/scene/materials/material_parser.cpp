#include "scene/materials/material_parser.hpp"

#include <cmath>

#include "scene/materials/normal_glints.hpp"
#include "scene/normal_maps/normal_map_parser.hpp"

namespace glintlab {

namespace {

// The keys of a glinty material (docs/scene-format.md): a Beckmann microsurface given by its
// slope deviations sigma (alpha = sqrt(2) sigma) and correlation rho, made of discrete microfacets.
void parse_glints(TomlReader& r, Material& m) {
  m.ndf = Ndf::Beckmann;
  m.alpha = std::sqrt(2.0f) * r.get_vec2("sigma", glm::vec2(0.1f), 0.005, 0.7);
  m.rho = static_cast<float>(r.get_number("rho", 0.0, -0.99, 0.99));
  GlintParams g;
  g.log_density = static_cast<float>(r.get_number("log_density", g.log_density, 0.0, 60.0));
  g.relative_area = static_cast<float>(r.get_number("relative_area", g.relative_area, 0.0, 1.0));
  g.max_anisotropy = static_cast<float>(r.get_number("max_anisotropy", g.max_anisotropy, 1.0, 64.0));
  m.glints = g;
}

// The keys of a binomial-glints material (docs/scene-format.md; Deliot & Belcour 2023): discrete
// microfacets whose expected NDF is GGX of roughness alpha.
void parse_binomial_glints(TomlReader& r, Material& m) {
  if (r.has("ndf")) r.fail("ndf", "is not a key of a binomial-glints material; its NDF is GGX (of roughness alpha)");
  m.ndf = Ndf::GGX;
  m.alpha = r.get_vec2("alpha", glm::vec2(0.2f), 0.01, 1.0);
  BinomialGlintParams g;
  g.log_density = static_cast<float>(r.get_number("log_density", g.log_density, 0.0, 50.0));
  g.microfacet_roughness =
      static_cast<float>(r.get_number("microfacet_roughness", g.microfacet_roughness, 1e-4, 1.0));
  g.density_randomization =
      static_cast<float>(r.get_number("density_randomization", g.density_randomization, 0.0, 10.0));
  g.slope_grid_scale = static_cast<float>(r.get_number("slope_grid_scale", g.slope_grid_scale, 0.1, 1000.0));
  m.binomial_glints = g;
}

// The keys of a normal-map-glints material (docs/scene-format.md; Yan et al. 2016): the normal map
// is the microsurface, each point's projected normal Gaussian of deviation intrinsic_roughness
// about the map's. Other methods shade Beckmann of alpha = sqrt(2) sigma_r over the normal map.
// The masking alpha needs the map: parse_material sets it once the map is read.
void parse_normal_glints(TomlReader& r, Material& m) {
  for (const char* key : {"alpha", "ndf", "sigma"})
    if (r.has(key))
      r.fail(key, "is not a key of a normal-map-glints material; its roughness is intrinsic_roughness "
                  "(Beckmann, alpha = sqrt(2) intrinsic_roughness) about the normal map's normals");
  if (!r.has("normal_map"))
    r.fail("normal_map", "is required by normal-map-glints material '" + m.name +
                             "' (the map is its microsurface); allowed: a table { file = ... } or { generator = ... }");
  NormalGlintParams g;
  g.intrinsic_roughness =
      static_cast<float>(r.get_number("intrinsic_roughness", g.intrinsic_roughness, 0.001, 0.3));
  m.ndf = Ndf::Beckmann;
  m.alpha = glm::vec2(std::sqrt(2.0f) * g.intrinsic_roughness);
  m.normal_glints = g;
}

}  // namespace

Material parse_material(TomlReader r, const std::filesystem::path& base_dir) {
  Material m;
  m.name = r.require_string("name");
  const std::string type =
      r.get_string("type", "microfacet", {"microfacet", "glinty", "binomial-glints", "normal-map-glints"});
  if (type == "glinty") {
    for (const char* key : {"alpha", "ndf"})
      if (r.has(key)) r.fail(key, "is not a key of a glinty material; it has sigma (alpha = sqrt(2) sigma) and a Beckmann NDF");
    parse_glints(r, m);
  } else if (type == "binomial-glints") {
    parse_binomial_glints(r, m);
  } else if (type == "normal-map-glints") {
    parse_normal_glints(r, m);
  } else {
    m.ndf = r.get_string("ndf", "ggx", {"ggx", "beckmann"}) == "ggx" ? Ndf::GGX : Ndf::Beckmann;
    m.alpha = r.get_vec2("alpha", m.alpha, 0.0, 1.0);
  }
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
  m.normal_map_tiling = static_cast<float>(r.get_number("normal_map_tiling", 1.0, 1e-3, 1e5));
  if (m.normal_glints)
    m.normal_glints->masking_alpha = normal_glint_masking_alpha(*m.normal_map, m.normal_glints->intrinsic_roughness);
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
