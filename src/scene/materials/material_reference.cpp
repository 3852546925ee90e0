#include "scene/materials/material_reference.hpp"

#include "core/markdown_cell.hpp"

#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {

std::string source_file(const MaterialKind& k) {
  std::string name = k.id;
  for (char& c : name)
    if (c == '-') c = '_';
  return "src/scene/materials/" + name + ".cpp";
}

}  // namespace

std::string material_reference_markdown(const std::vector<MaterialKind>& kinds) {
  std::string out = "\n";
  for (const MaterialKind& k : kinds) {
    out += "### `type = \"" + k.id + "\"`: " + k.title + "\n\n";
    out += k.summary + "\n\n";
    out += "Source: " + k.citation + ".\n\n";
    out += "Descriptor `" + source_file(k) + "`, shading `shaders/" + k.glsl_file() + "`.\n\n";
    if (k.lobe_keys.empty() && k.params.empty() && !k.requires_normal_map) {
      out += "Keys of its own: none.\n\n";
      continue;
    }
    out += "| key | type | default | allowed | meaning |\n| --- | --- | --- | --- | --- |\n";
    if (k.requires_normal_map)
      out += "| `normal_map` | table | required | a file or a generator (below) | the microsurface itself; missing is "
             "exit 2 naming the material |\n";
    for (const MaterialKeyDoc& d : k.lobe_keys)
      out += "| `" + d.key + "` | " + d.type + " | " + markdown_cell(d.default_text) + " | " + markdown_cell(d.allowed) + " | " +
             markdown_cell(d.meaning) + " |\n";
    for (const MaterialParamDecl& p : k.params)
      if (!p.derived)
        out += "| `" + p.key + "` | number | " + number_text(p.default_value) + " | " + range_text(p.min, p.max) +
               " | " + markdown_cell(p.description) + " |\n";
    for (const MaterialParamDecl& p : k.params)
      if (p.derived) out += "\nDerived (not a key): `" + p.key + "`, " + p.description + ".\n";
    out += "\n";
  }
  return out;
}

std::string material_listing(const std::vector<MaterialKind>& kinds) {
  std::string out;
  for (const MaterialKind& k : kinds) {
    out += k.id + " — " + k.title + "\n  " + k.summary + "\n";
    if (k.requires_normal_map) out += "  normal_map = {...}  (required)\n";
    for (const MaterialKeyDoc& d : k.lobe_keys)
      out += "  " + d.key + " = " + d.default_text + "  (" + d.allowed + ") " + d.meaning + "\n";
    for (const MaterialParamDecl& p : k.params)
      if (!p.derived)
        out += "  " + p.key + " = " + number_text(p.default_value) + "  (" + range_text(p.min, p.max) + ") " +
               p.description + "\n";
    out += "\n";
  }
  return out;
}

}  // namespace glintlab
