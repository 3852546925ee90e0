#include "shading/method_reference.hpp"

#include "core/markdown_cell.hpp"

namespace glintlab {

namespace {

std::string parameters_markdown(const MethodDescriptor& m) {
  if (m.params.empty()) return "Parameters: none.\n";
  std::string out = "| parameter | default | allowed | description |\n| --- | --- | --- | --- |\n";
  for (const ParamDecl& p : m.params)
    out += "| `" + p.name + "` | `" + markdown_cell(p.default_text()) + "` | `" + markdown_cell(p.allowed()) + "` | " +
           markdown_cell(p.description) + " |\n";
  return out;
}

std::string tables_markdown(const MethodDescriptor& m) {
  std::string resources;
  if (!m.resources.empty()) {
    resources = "Other resources (src/render/resources/):\n\n";
    for (const std::string& id : m.resources) resources += "- " + id + "\n";
  }
  if (all_tables_of(m).empty()) return "Precomputed tables: none.\n" + (resources.empty() ? "" : "\n" + resources);
  std::string out = "Precomputed tables:\n\n";
  for (const std::string& table : m.tables) out += "- " + table + "\n";
  for (const ParamDecl& p : m.params)
    for (std::size_t c = 0; c < p.choice_tables.size(); ++c)
      for (const std::string& table : p.choice_tables[c])
        out += "- " + table + " (with `" + p.name + " = " + p.choices[c] + "`)\n";
  return out + (resources.empty() ? "" : "\n" + resources);
}

}  // namespace

std::string method_reference_markdown(const std::vector<MethodDescriptor>& methods) {
  std::string out = "\n";
  for (const MethodDescriptor& m : methods) {
    out += "### `" + m.id + "`: " + m.title + "\n\n";
    out += m.summary + "\n\n";
    out += "Source: " + m.citation + ".\n\n";
    out += "Module `shaders/" + m.module_path() + "`, descriptor `src/shading/methods/" + m.id +
           ".cpp`; derivation and tests: [" + m.id + "](#" + m.id + ").\n\n";
    out += parameters_markdown(m) + "\n";
    out += tables_markdown(m) + "\n";
  }
  return out;
}

}  // namespace glintlab
