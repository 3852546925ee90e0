#include "export/export_command.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/cache_directory.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/output_stage.hpp"
#include "eval/program_command.hpp"
#include "export/exported_shader.hpp"
#include "export/export_readme.hpp"
#include "export/texture_file.hpp"
#include "gl/context.hpp"
#include "render/renderer.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/materials/material_kind.hpp"
#include "tables/registry.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {

namespace {

std::string quoted(const std::filesystem::path& p) {
  std::string s = "'";
  for (char c : p.string()) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a tool of the export; its output goes to `log`, quoted in the failure.
void run_tool(const std::string& tool, const std::string& package, const std::string& arguments,
              const std::filesystem::path& log) {
  if (std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) != 0)
    throw RuntimeFailure("export: " + tool + " not found; install Debian's " + package);
  if (std::system((tool + " " + arguments + " >" + quoted(log) + " 2>&1").c_str()) != 0)
    throw RuntimeFailure("export: " + tool + " " + arguments + " failed (a glintlab bug: please report it):\n" +
                         read_text(log));
}

const LightKind& light_kind(const std::string& id) {
  std::string ids;
  for (const LightKind& k : all_light_kinds()) {
    if (k.id == id) return k;
    ids += (ids.empty() ? "" : ", ") + k.id;
  }
  throw InputError("--light " + id + ": allowed: " + ids);
}

}  // namespace

std::vector<std::string> run_export(const ExportOptions& o) {
  // Every option checked before anything is written.
  if (o.out.empty()) throw InputError("-o: the directory to export into is required");
  check_output_directory(o.out);
  DriverProfile profile = DriverProfile::Hardware;
  if (o.driver_profile == "software") profile = DriverProfile::Software;
  else if (o.driver_profile != "hardware")
    throw InputError("--driver-profile " + o.driver_profile + ": allowed: hardware, software");
  const std::vector<MethodChoice> choices = resolve_methods(o.method, o.params);
  if (choices.size() != 1) throw InputError("--method " + o.method + ": one method or variant");
  const MethodChoice& method = choices.front();
  const MaterialVariant material = program_material_variant(o.material_kind, o.normal_map, o.textures, o.anisotropic);
  const LightKind& light = light_kind(o.light);
  const MaterialKind& kind = o.material_kind.empty() ? default_material_kind() : find_material_kind(o.material_kind);
  const std::string stem = method.file_stem() + "." + kind.id + "." + light.id;

  const ExportedShader shader = export_shader(method, material, light, profile);
  OutputStage stage(o.out);
  const std::filesystem::path& dir = stage.path();
  const std::filesystem::path glsl = dir / (stem + ".glsl"), spirv = dir / (stem + ".spv"), log = dir / ".tool.log";
  std::ofstream(glsl) << shader.glsl;
  run_tool("glslangValidator", "glslang-tools",
           "-V --target-env vulkan1.1 -S frag -o " + quoted(spirv) + " " + quoted(glsl), log);
  run_tool("spirv-cross", "spirv-cross",
           quoted(spirv) + " --hlsl --shader-model 50 --output " + quoted(dir / (stem + ".hlsl")), log);
  run_tool("spirv-cross", "spirv-cross", quoted(spirv) + " --msl --output " + quoted(dir / (stem + ".metal")), log);
  run_tool("spirv-cross", "spirv-cross", quoted(spirv) + " --reflect --output " + quoted(dir / ".reflect.json"), log);
  const nlohmann::json reflection = nlohmann::json::parse(read_text(dir / ".reflect.json"));
  std::filesystem::remove(dir / ".reflect.json");
  std::filesystem::remove(log);

  // The tables the compiled shader samples, as the GL holds them.
  std::vector<ExportedTable> tables;
  for (const ExportedTable& t : shader.tables)
    for (const auto& texture : reflection.value("textures", nlohmann::json::array()))
      if (texture.value("name", "") == t.sampler) tables.push_back(t);
  std::vector<std::string> files{stem + ".glsl", stem + ".spv", stem + ".hlsl", stem + ".metal"};
  if (!tables.empty()) {
    const auto context = GlContext::create_headless();
    const TableCache cache(default_table_cache_directory());
    for (const ExportedTable& t : tables) {
      const Table& table = find_table(t.id);
      const gl::Texture texture = table.upload(cache.load_or_generate(table.source).values);
      write_texture_file(dir / (t.id + ".table"), read_texture(texture.id()));
      files.push_back(t.id + ".table");
    }
  }
  std::ofstream(dir / "README.md") << export_readme({stem, method, kind, light, shader, tables, reflection});
  files.push_back("README.md");
  stage.publish({"README.md"});
  return files;
}

}  // namespace glintlab
