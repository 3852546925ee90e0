#include "export/export_readme.hpp"

#include <sstream>

#include "core/gpu_contract.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/materials/material_kind.hpp"

namespace glintlab {

namespace {

// What glintlab binds at a texture the compiled code samples that is not a table.
std::string texture_role(const std::string& name) {
  if (name == "uNormalMap") return "the material's normal map (RGB: the normal in tangent space, as glTF's)";
  if (name == "uBaseColor") return "the material's base colour texture (sRGB)";
  if (name == "uMetallicRoughness") return "the material's metallic-roughness texture (glTF's: g roughness, b metallic)";
  if (name == "uEmissive") return "the material's emissive texture (sRGB)";
  if (name.starts_with("uEnvironment"))
    return "the environment light's data, made per environment map by glintlab (src/render/resources/)";
  return "a per-scene resource made by glintlab (see the method's docs)";
}

std::string value_text(const ParamDecl& p, const ParamValues& values) {
  const float v = values.count(p.name) ? values.at(p.name) : p.default_value;
  if (p.is_enumeration()) return p.choices.at(static_cast<std::size_t>(v));
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string export_readme(const ExportReadme& r) {
  std::ostringstream s;
  const MethodDescriptor& m = *r.method.method;
  s << "# " << r.method.display_name() << " for a " << r.kind.id << " material under a " << r.light.id
    << " light\n\n"
    << m.title << " (" << m.citation << "), exported by `glintlab export` from glintlab's own shaders.\n\n"
    << "| file | what |\n| --- | --- |\n"
    << "| `" << r.stem << ".glsl` | GLSL 4.50 (Vulkan-style: blocks and bindings, no loose uniforms): the entry "
       "point `glintlabShade` and an example `main` (define `GLINTLAB_NO_MAIN` to leave it out) |\n"
    << "| `" << r.stem << ".spv` | its SPIR-V (fragment stage, entry `main`) |\n"
    << "| `" << r.stem << ".hlsl` | HLSL (shader model 5.0), translated from the SPIR-V by spirv-cross |\n"
    << "| `" << r.stem << ".metal` | MSL, translated from the SPIR-V by spirv-cross |\n";
  for (const ExportedTable& t : r.tables) s << "| `" << t.id << ".table` | the table `" << t.sampler << "` samples |\n";
  s << "\n## Entry point\n\n```glsl\n"
       "struct GlintlabRadiance { vec3 diffuse; vec3 specular; vec3 emission; };\n"
       "GlintlabRadiance glintlabShade(int material, vec3 position, vec3 normal, vec4 tangent, vec2 texcoord,\n"
       "                               LightData light);\n```\n\n"
       "Call it from a fragment shader in uniform control flow (it takes screen-space derivatives of its inputs: "
       "they are the pixel's footprint). `position`, `normal`, `tangent` (w: the bitangent's sign) are the "
       "surface's interpolated world-space attributes, `texcoord` its texture coordinates, `material` the index of "
       "its MaterialData in `MaterialBlock`; `light` is one light of "
       "the kind `"
    << r.light.id
    << "`, packed as glintlab packs it (src/scene/lights/" << r.light.id
    << ".cpp); the camera is `FrameBlock`'s (`camera_pos`: w = 1 for a perspective camera; `camera_forward`). "
       "The radiance of one light: sum `diffuse + specular` over your lights, add `emission` once. "
       "`MaterialData`, `LightData` and `FrameData` are std140 structs declared at the top of the GLSL file "
       "(generated from src/core/gpu_contract.hpp's field lists).\n\n";
  // The records from their one declaration (src/core/gpu_contract.hpp).
  auto fields = [&](const char* record, const char* how, const auto& list) {
    s << "`" << record << "` (std140) " << how << ":\n\n| field | type | meaning |\n| --- | --- | --- |\n";
    for (const Std140Field& f : list) s << "| `" << f.name << "` | " << f.glsl_type << " | " << f.meaning << " |\n";
    s << "\n";
  };
  fields("MaterialData", "as glintlab packs a material (pack_material, src/render/gpu_scene.cpp)", kMaterialFields);
  if (!r.kind.params.empty()) {
    s << "`kind_params` of a " << r.kind.id << " material, in order (x, y, z, w):\n\n";
    for (const MaterialParamDecl& p : r.kind.params)
      s << "- `" << p.key << "` (" << p.min << " .. " << p.max << ", default " << p.default_value << "): "
        << p.description << "\n";
    s << "\n";
  }
  fields("LightData", "as glintlab packs a light (pack_light: the kind's own packing, colour_type.a its code)",
         kLightFields);
  fields("FrameData", "as glintlab fills it for a view (frame_uniforms, src/render/renderer.cpp)", kFrameFields);
  s << "For one view: `target` = (width, height, 1, 0) and `tile` = (0, 0, 1, 0); `target.w` must stay 0.\n\n";
  s << "## What the compiled code reads\n\nFrom spirv-cross's reflection of the SPIR-V; bind these, nothing "
       "else is read. Bindings are OpenGL's (uniform blocks and texture units count apart); for Vulkan, give the "
       "textures a set of their own or shift them.\n\n| resource | kind | binding | what |\n| --- | --- | --- | --- |\n";
  for (const auto& ubo : r.reflection.value("ubos", nlohmann::json::array()))
    s << "| `" << ubo.value("name", "") << "` | uniform block, " << ubo.value("block_size", 0) << " bytes | "
      << ubo.value("binding", -1) << " | "
      << (ubo.value("name", "") == "FrameBlock"      ? "the camera (FrameData)"
          : ubo.value("name", "") == "LightBlock"    ? "the example main's light (lights[0]; glintlabShade takes its light as an argument)"
          : ubo.value("name", "") == "MaterialBlock" ? "the materials (MaterialData), indexed by glintlabShade's `material`"
          : ubo.value("name", "") == "TextureTransformBlock"
              ? "each material texture's uv transform (mat3x2 per TEXTURE_SLOT_*; identity: no tiling)"
              : "see the GLSL")
      << " |\n";
  for (const auto& tex : r.reflection.value("textures", nlohmann::json::array())) {
    const std::string name = tex.value("name", "");
    std::string what = texture_role(name);
    for (const ExportedTable& t : r.tables)
      if (t.sampler == name) what = "`" + t.id + ".table`";
    s << "| `" << name << "` | " << tex.value("type", "") << " | " << tex.value("binding", -1) << " | " << what
      << " |\n";
  }
  if (!r.shader.resources.empty()) {
    s << "\nPer-scene resources the method reads (";
    for (std::size_t i = 0; i < r.shader.resources.size(); ++i) s << (i ? ", " : "") << "`" << r.shader.resources[i] << "`";
    s << ") are made by glintlab for each scene and normal map; they are not exported (see docs/methods.md).\n";
  }
  s << "\n## Parameters\n\nBaked in as constants (export again with `--param name=value` for others):\n\n";
  if (m.params.empty()) s << "none\n";
  for (const ParamDecl& p : m.params)
    if (!p.host_only) s << "- `" << p.name << "` = " << value_text(p, r.method.params) << " (" << p.allowed() << ")\n";
  s << "\n## Table files\n\nA 64-byte little-endian header, then each mip level's texels as RGBA float32 "
       "(level 0 first; each level layer by layer, rows from v = 0, texels from u = 0):\n\n"
       "| bytes | field |\n| --- | --- |\n"
       "| 0-7 | `GLNTTEX\\0` |\n| 8-11 | version (1) |\n| 12-15 | GL target (e.g. 0x8C1A `GL_TEXTURE_2D_ARRAY`) |\n"
       "| 16-19 | the internal format it is sampled in (e.g. 0x881A `GL_RGBA16F`) |\n"
       "| 20-31 | width, height, depth of level 0 (a 1D array's layers are its height, a 2D array's its depth) |\n"
       "| 32-35 | mip levels |\n| 36-51 | min filter, mag filter, wrap s, wrap t (GL enums) |\n"
       "| 52-55 | channels stored (4) |\n| 56-63 | reserved (0) |\n\n"
       "Upload each level with the stated format, filters and wraps, and bind it at the table's binding.\n";
  return s.str();
}

}  // namespace glintlab
