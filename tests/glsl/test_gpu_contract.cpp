// The C++/GLSL contract (src/core/gpu_contract.hpp): the defines the shaders get are the C++
// constants, and the driver lays the uniform blocks out where the C++ records put their fields.
#include <gtest/gtest.h>

#include <cctype>
#include <cstddef>

#include "core/pixel_filter_width.hpp"
#include "gl_fixture.hpp"
#include "tables/registry.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

/// The values of GLSL integer expressions, evaluated on the device.
std::vector<int> glsl_values(const std::string& includes, const std::vector<std::string>& expressions) {
  std::string body = "vec4 evaluate(vec4 a, vec4 b) {\n  int i = int(a.x);\n";
  for (std::size_t i = 0; i < expressions.size(); ++i)
    body += "  if (i == " + std::to_string(i) + ") return vec4(float(" + expressions[i] + "));\n";
  body += "  return vec4(-1.0);\n}\n";
  std::vector<glm::vec4> a;
  for (std::size_t i = 0; i < expressions.size(); ++i) a.emplace_back(static_cast<float>(i), 0, 0, 0);
  std::vector<int> out;
  for (const auto& v : evaluate_glsl(includes, body, a, a)) out.push_back(static_cast<int>(v.x));
  return out;
}

/// Offset (bytes) of a member of an active uniform block, by its GLSL name; -1 if absent.
GLint uniform_offset(GLuint program, const char* name) {
  const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name);
  if (index == GL_INVALID_INDEX) return -1;
  const GLenum prop = GL_OFFSET;
  GLint offset = -1;
  glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &prop, 1, nullptr, &offset);
  return offset;
}

/// A property (GL_BUFFER_DATA_SIZE, GL_BUFFER_BINDING) of the uniform block `name`, or -1.
GLint block_property(GLuint program, const char* name, GLenum property) {
  const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM_BLOCK, name);
  if (index == GL_INVALID_INDEX) return -1;
  GLint value = -1;
  glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, index, 1, &property, 1, nullptr, &value);
  return value;
}
GLint block_size(GLuint program, const char* name) { return block_property(program, name, GL_BUFFER_DATA_SIZE); }
GLint block_binding(GLuint program, const char* name) { return block_property(program, name, GL_BUFFER_BINDING); }

GLint sampler_unit(GLuint program, const char* name) {
  GLint unit = -1;
  glGetUniformiv(program, glGetUniformLocation(program, name), &unit);
  return unit;
}

}  // namespace

TEST(GpuContract, GeneratedDefinesAreTheCppConstants) {
  struct Expected {
    const char* define;
    int value;
  };
  std::vector<Expected> expected = {
      {"MAX_LIGHTS", kMaxLights},
      {"MAX_MATERIALS", kMaxMaterials},
      {"FRAME_BLOCK_BINDING", kFrameBlockBinding},
      {"LIGHT_BLOCK_BINDING", kLightBlockBinding},
      {"MATERIAL_BLOCK_BINDING", kMaterialBlockBinding},
      {"PREFILTERED_NDF_RECORDS_BINDING", kPrefilteredNdfRecordsBinding},
      {"PREFILTERED_NDF_VALUES_BINDING", kPrefilteredNdfValuesBinding},
      {"NORMAL_MAP_UNIT", kNormalMapUnit},
      {"SLOPE_MOMENTS_UNIT", kSlopeMomentsUnit},
      {"SLOPE_CROSS_MOMENT_UNIT", kSlopeCrossMomentUnit},
      {"BASE_COLOR_UNIT", kBaseColorUnit},
      {"METALLIC_ROUGHNESS_UNIT", kMetallicRoughnessUnit},
      {"EMISSIVE_UNIT", kEmissiveUnit},
      {"TEXTURE_SLOT_NORMAL_MAP", kTextureSlotNormalMap},
      {"TEXTURE_SLOT_BASE_COLOR", kTextureSlotBaseColor},
      {"TEXTURE_SLOT_METALLIC_ROUGHNESS", kTextureSlotMetallicRoughness},
      {"TEXTURE_SLOT_EMISSIVE", kTextureSlotEmissive},
      {"TEXTURE_SLOTS", kTextureSlots},
      {"FIRST_TABLE_UNIT", kFirstTableUnit},
      {"NDF_GGX", kNdfGgx},
      {"NDF_BECKMANN", kNdfBeckmann},
      {"LIGHT_FORM_NONE", static_cast<int>(LightForm::None)},
      {"LIGHT_FORM_DISK", static_cast<int>(LightForm::Disk)},
      {"LIGHT_FORM_POLYGON", static_cast<int>(LightForm::Polygon)},
      {"LIGHT_KIND_COUNT", static_cast<int>(all_light_kinds().size())},
  };
  std::vector<std::string> table_units;  // kept alive: Expected holds the names' pointers
  for (const auto& t : all_tables()) table_units.push_back(table_define(t.source.id));
  for (std::size_t i = 0; i < table_units.size(); ++i)
    expected.push_back({table_units[i].c_str(), kFirstTableUnit + static_cast<int>(i)});
  std::vector<std::string> expressions;
  for (const auto& e : expected) expressions.push_back(e.define);
  for (const auto& k : all_light_kinds()) {
    std::string define = "LIGHT_";
    for (char c : k.id) define += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    expressions.push_back(define);
  }
  for (const auto& k : all_material_kinds()) expressions.push_back(k.define());
  const auto values = glsl_values("#include \"generated/gpu_contract.glsl\"\n", expressions);
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(values[i], expected[i].value) << expected[i].define;
  for (std::size_t k = 0; k < all_light_kinds().size(); ++k)
    EXPECT_EQ(values[expected.size() + k], all_light_kinds()[k].code()) << expressions[expected.size() + k];
  const std::size_t first_material = expected.size() + all_light_kinds().size();
  for (std::size_t k = 0; k < all_material_kinds().size(); ++k)
    EXPECT_EQ(values[first_material + k], all_material_kinds()[k].code()) << expressions[first_material + k];
  const std::size_t float_defines = 1;  // PIXEL_FILTER_SIGMA: GeneratedPixelFilterSigmaIsTheCppConstant
  EXPECT_EQ(contract_defines().size(), expressions.size() + float_defines) << "a define this test does not check";
}

TEST(GpuContract, GeneratedPixelFilterSigmaIsTheCppConstant) {
  // The one pixel-filter width (src/core/pixel_filter_width.hpp) as the shaders see it: a float.
  const auto v = evaluate_glsl("#include \"generated/gpu_contract.glsl\"\n",
                               "vec4 evaluate(vec4 a, vec4 b) { float s = PIXEL_FILTER_SIGMA; return vec4(s); }",
                               {glm::vec4(0.0f)}, {glm::vec4(0.0f)});
  EXPECT_EQ(v[0].x, kPixelFilterSigma);
}

/// The GLSL expression that reads every field of a record (so that the driver keeps them all), and
/// the expected std140 offset of each, from the record's field list in src/core/gpu_contract.hpp.
template <std::size_t N>
std::string read_every_field(const std::string& prefix, const Std140Field (&fields)[N]) {
  std::string sum;
  for (const Std140Field& f : fields) {
    const std::string name = prefix + f.name;
    const std::string type = f.glsl_type;
    sum += (sum.empty() ? "" : " + ") + (type == "mat4" ? name + "[0]" : type == "ivec4" ? "vec4(" + name + ")" : name);
  }
  return sum;
}

template <std::size_t N>
void expect_offsets(GLuint program, const std::string& prefix, const Std140Field (&fields)[N], std::size_t record_size,
                    const std::string& next_record) {
  std::size_t offset = 0;
  for (const Std140Field& f : fields) {
    EXPECT_EQ(uniform_offset(program, (prefix + f.name).c_str()), static_cast<GLint>(offset)) << prefix << f.name;
    offset += std140_size(f.glsl_type);
  }
  EXPECT_EQ(offset, record_size) << prefix;
  if (!next_record.empty()) {
    EXPECT_EQ(uniform_offset(program, next_record.c_str()), static_cast<GLint>(record_size));
  }
}

TEST(GpuContract, Std140LayoutsMatchTheCppRecords) {
  // The driver's offsets of every member of the three uniform blocks, their bindings and sizes,
  // in a program that declares them the way the forward pass does; the members come from the
  // same field lists as the C++ records and the generated GLSL structs.
  shaders().add_source("test/contract_layout.comp", R"(
layout(local_size_x = 1) in;
#include "core/frame.glsl"
#include "lights/light_data.glsl"
#include "core/material.glsl"
#include "glints/chermain/dictionary.glsl"
#include "lobe/slope_moments.glsl"
#include "core/material_textures.glsl"
layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uNormalMapProbe;
layout(std430, binding = 7) writeonly buffer Out { vec4 outV[]; };
void main() {
  outV[0] = )" + read_every_field("frame.", kFrameFields) + R"(;
  outV[1] = lights[1].colour_type + )" + read_every_field("lights[0].", kLightFields) + R"(;
  outV[2] = materials[1].f0_ndf + )" + read_every_field("materials[0].", kMaterialFields) + R"(;
  outV[3] = textureLod(uNormalMapProbe, vec2(0.0), 0.0) + textureLod(uSlopeMoments, vec2(0.0), 0.0) +
            textureLod(uSlopeCrossMoment, vec2(0.0), 0.0) + textureLod(uGlintDictionary, vec2(0.0), 0.0);
  outV[4] = textureLod(uBaseColor, vec2(0.0), 0.0) + textureLod(uMetallicRoughness, vec2(0.0), 0.0) +
            textureLod(uEmissive, vec2(0.0), 0.0);
}
)");
  const GLuint program = shaders().compute("test/contract_layout.comp");
  EXPECT_EQ(block_binding(program, "FrameBlock"), kFrameBlockBinding);
  EXPECT_EQ(block_binding(program, "LightBlock"), kLightBlockBinding);
  EXPECT_EQ(block_binding(program, "MaterialBlock"), kMaterialBlockBinding);
  EXPECT_EQ(block_size(program, "FrameBlock"), static_cast<GLint>(sizeof(FrameUniforms)));
  EXPECT_EQ(block_size(program, "LightBlock"), static_cast<GLint>(kMaxLights * sizeof(LightGpu)));
  EXPECT_EQ(block_size(program, "MaterialBlock"), static_cast<GLint>(kMaxMaterials * sizeof(MaterialGpu)));
  expect_offsets(program, "frame.", kFrameFields, sizeof(FrameUniforms), "");
  expect_offsets(program, "lights[0].", kLightFields, sizeof(LightGpu), "lights[1].colour_type");
  expect_offsets(program, "materials[0].", kMaterialFields, sizeof(MaterialGpu), "materials[1].f0_ndf");
  // The C++ records' own offsets, member by member, against the same lists.
  EXPECT_EQ(offsetof(FrameUniforms, tile), 112u);
  EXPECT_EQ(offsetof(LightGpu, axis_v), 64u);
  EXPECT_EQ(offsetof(MaterialGpu, dielectric_f0), 112u);

  EXPECT_EQ(sampler_unit(program, "uNormalMapProbe"), kNormalMapUnit);
  EXPECT_EQ(sampler_unit(program, "uSlopeMoments"), kSlopeMomentsUnit);
  EXPECT_EQ(sampler_unit(program, "uSlopeCrossMoment"), kSlopeCrossMomentUnit);
  EXPECT_EQ(sampler_unit(program, "uGlintDictionary"), find_table("glint-dictionary").unit);
  EXPECT_EQ(sampler_unit(program, "uBaseColor"), kBaseColorUnit);
  EXPECT_EQ(sampler_unit(program, "uMetallicRoughness"), kMetallicRoughnessUnit);
  EXPECT_EQ(sampler_unit(program, "uEmissive"), kEmissiveUnit);
}

TEST(GpuContract, NoShaderRestatesWhatIsGenerated) {
  // The records, the kinds' codes and the material kinds' parameters live only in generated/*.glsl:
  // a hand copy in a shader file would drift from the C++ side unseen.
  std::vector<std::string> generated_only = {"struct LightData", "struct MaterialData", "struct FrameData",
                                             "#define LIGHT_KIND_COUNT", ".kind_params."};
  for (const auto& [name, value] : contract_defines()) generated_only.push_back("#define " + name + " ");
  int files = 0;
  for (const std::string& path : shaders().paths()) {
    if (path.starts_with("generated/")) continue;
    const std::string text = shaders().source(path);
    for (const std::string& s : generated_only) EXPECT_EQ(text.find(s), std::string::npos) << path << " has " << s;
    ++files;
  }
  EXPECT_GT(files, 50);
}
