// The C++/GLSL contract (src/core/gpu_contract.hpp): the defines the shaders get are the C++
// constants, and the driver lays the uniform blocks out where the C++ records put their fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>

#include "core/pixel_filter_width.hpp"
#include "gl_fixture.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"
#include "shading/registry.hpp"
#include "tables/glint_dictionary/glint_dictionary.hpp"
#include "tables/ltc/ltc_table.hpp"
#include "tables/registry.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

/// The values of GLSL int or float expressions, evaluated on the device (as floats: exact for the
/// contract's small integers).
std::vector<float> glsl_values(const std::string& includes, const std::vector<std::string>& expressions) {
  // In programs of at most 64 expressions: llvmpipe returned 0 for the last few of one chain of
  // some 140 branches.
  constexpr std::size_t kPerProgram = 64;
  std::vector<float> out;
  for (std::size_t first = 0; first < expressions.size(); first += kPerProgram) {
    const std::size_t count = std::min(kPerProgram, expressions.size() - first);
    std::string body = "vec4 evaluate(vec4 a, vec4 b) {\n  int i = int(a.x);\n";
    for (std::size_t i = 0; i < count; ++i)
      body += "  if (i == " + std::to_string(i) + ") return vec4(float(" + expressions[first + i] + "));\n";
    body += "  return vec4(-1.0);\n}\n";
    std::vector<glm::vec4> a;
    for (std::size_t i = 0; i < count; ++i) a.emplace_back(static_cast<float>(i), 0, 0, 0);
    for (const auto& v : evaluate_glsl(includes, body, a, a)) out.push_back(v.x);
  }
  return out;
}

/// The text with // and /* */ comments blanked (a name in a comment restates nothing).
std::string without_comments(std::string text) {
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '/' && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') text[i++] = ' ';
    } else if (text[i] == '/' && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? text.size() : end + 2;
      for (; i < stop; ++i)
        if (text[i] != '\n') text[i] = ' ';
      --i;
    }
  }
  return text;
}

/// Every enumeration the registered methods declare, each name once (the registry checked that
/// its choices agree; host-only ones never reach GLSL).
std::vector<const ParamDecl*> enumerations() {
  std::vector<const ParamDecl*> out;
  for (const MethodDescriptor& m : all_methods())
    for (const ParamDecl& p : m.params)
      if (p.is_enumeration() && !p.host_only &&
          std::none_of(out.begin(), out.end(), [&](const ParamDecl* q) { return q->name == p.name; }))
        out.push_back(&p);
  return out;
}

/// Every declaration of an enumeration by a registered method.
std::vector<const ParamDecl*> enumeration_declarations() {
  std::vector<const ParamDecl*> out;
  for (const MethodDescriptor& m : all_methods())
    for (const ParamDecl& p : m.params)
      if (p.is_enumeration() && !p.host_only) out.push_back(&p);
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
      {"POSITION_NORMAL_ELEMENT_NORMALS_BINDING", kPositionNormalElementNormalsBinding},
      {"POSITION_NORMAL_ELEMENT_JACOBIANS_BINDING", kPositionNormalElementJacobiansBinding},
      {"ENVIRONMENT_LOBES_BINDING", kEnvironmentLobesBinding},
      {"PATH_HITS_BINDING", kPathHitsBinding},
      {"PATH_SHADOW_RAYS_BINDING", kPathShadowRaysBinding},
      {"PATH_EMISSION_BINDING", kPathEmissionBinding},
      {"PATH_CONTINUATION_BINDING", kPathContinuationBinding},
      {"NORMAL_MAP_UNIT", kNormalMapUnit},
      {"SLOPE_MOMENTS_UNIT", kSlopeMomentsUnit},
      {"SLOPE_CROSS_MOMENT_UNIT", kSlopeCrossMomentUnit},
      {"BASE_COLOR_UNIT", kBaseColorUnit},
      {"METALLIC_ROUGHNESS_UNIT", kMetallicRoughnessUnit},
      {"EMISSIVE_UNIT", kEmissiveUnit},
      {"ENVIRONMENT_RADIANCE_UNIT", kEnvironmentRadianceUnit},
      {"ENVIRONMENT_CDF_UNIT", kEnvironmentCdfUnit},
      {"ENVIRONMENT_SPECULAR_UNIT", kEnvironmentSpecularUnit},
      {"ENVIRONMENT_IRRADIANCE_UNIT", kEnvironmentIrradianceUnit},
      {"ENVIRONMENT_GLINT_WEIGHTS_UNIT", kEnvironmentGlintWeightsUnit},
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
      {"REFERENCE_SURFACE_MODEL", static_cast<int>(ReferenceSurface::Model)},
      {"REFERENCE_SURFACE_REALISATION", static_cast<int>(ReferenceSurface::Realisation)},
      {"REFERENCE_SURFACE_FACETS", static_cast<int>(ReferenceSurface::Facets)},
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
  // The tables' constants: what each table declares from its generator's settings.
  std::vector<std::pair<std::string, float>> table_constants;
  for (const auto& t : all_tables())
    for (const TableConstant& c : t.glsl_constants)
      if (std::find(expressions.begin(), expressions.end(), c.name) == expressions.end()) {
        expressions.push_back(c.name);
        table_constants.emplace_back(c.name, static_cast<float>(c.value));
      }
  // The enumerations' choices: <PARAM>_<CHOICE> is the index the C++ side sets the parameter to
  // for that choice (resolve_params), in every method that declares it.
  const std::size_t first_choice = expressions.size();
  std::vector<std::pair<const ParamDecl*, std::size_t>> choices;  // (enumeration, choice index)
  for (const ParamDecl* p : enumeration_declarations())
    for (std::size_t c = 0; c < p->choices.size(); ++c) {
      const std::string define = choice_define(p->name, p->choices[c]);
      if (std::find(expressions.begin() + static_cast<std::ptrdiff_t>(first_choice), expressions.end(), define) ==
          expressions.end())
        expressions.push_back(define);
      choices.emplace_back(p, c);
    }
  const auto values = glsl_values("#include \"generated/gpu_contract.glsl\"\n", expressions);
  const auto value_of = [&](const std::string& define) {
    return values[static_cast<std::size_t>(std::find(expressions.begin(), expressions.end(), define) -
                                           expressions.begin())];
  };
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(values[i], static_cast<float>(expected[i].value)) << expected[i].define;
  for (std::size_t k = 0; k < all_light_kinds().size(); ++k)
    EXPECT_EQ(values[expected.size() + k], all_light_kinds()[k].code()) << expressions[expected.size() + k];
  const std::size_t first_material = expected.size() + all_light_kinds().size();
  for (std::size_t k = 0; k < all_material_kinds().size(); ++k)
    EXPECT_EQ(values[first_material + k], all_material_kinds()[k].code()) << expressions[first_material + k];
  for (const auto& [name, value] : table_constants) EXPECT_EQ(value_of(name), value) << name;
  EXPECT_FALSE(table_constants.empty());
  for (const auto& [p, c] : choices)
    EXPECT_EQ(value_of(choice_define(p->name, p->choices[c])), static_cast<float>(c))
        << p->name << " = " << p->choices[c];
  EXPECT_GT(choices.size(), 20u);
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

TEST(GpuContract, TableConstantsAreTheGeneratorsSettings) {
  // The tables declare their GLSL constants from the generators' own settings; the shaders read
  // them as the layout they address.
  const GlintDictionarySettings dictionary;
  const auto values = glsl_values("#include \"generated/gpu_contract.glsl\"\n",
                                  {"GLINT_MARGINALS", "GLINT_LEVELS", "GLINT_DICT_SIGMA", "GLINT_SLOPE_RANGE",
                                   "LTC_TABLE_SIZE", "GLINT_MARGINALS / 3", "LTC_TABLE_SIZE * 0.5"});
  EXPECT_EQ(values[0], static_cast<float>(dictionary.marginals));
  EXPECT_EQ(values[1], static_cast<float>(dictionary.levels));
  EXPECT_EQ(values[2], dictionary.sigma());
  EXPECT_EQ(values[3], dictionary.slope_range());
  EXPECT_EQ(values[4], static_cast<float>(kLtcTableSize));
  EXPECT_EQ(values[5], static_cast<float>(dictionary.marginals / 3)) << "an int in GLSL";
  EXPECT_EQ(values[6], 0.5f * kLtcTableSize) << "a float in GLSL";
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

namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Where `text` holds `word` as a whole identifier, each followed by what comes after it (spaces
/// skipped) and preceded by what comes before it (spaces skipped).
struct Use {
  std::string before, after;
};
std::vector<Use> uses_of(const std::string& text, const std::string& word) {
  std::vector<Use> out;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    if ((at > 0 && identifier_char(text[at - 1])) || (end < text.size() && identifier_char(text[end]))) continue;
    std::size_t b = at, a = end;
    while (b > 0 && text[b - 1] == ' ') --b;
    while (a < text.size() && text[a] == ' ') ++a;
    out.push_back({text.substr(b >= 8 ? b - 8 : 0, b >= 8 ? 8 : b), text.substr(a, 16)});
  }
  return out;
}

/// Whether a use declares the name: `#define NAME`, `NAME = ...` (a const), never `NAME == ...`.
bool declares(const Use& u) {
  return u.before.ends_with("#define") || (u.after.starts_with("=") && !u.after.starts_with("=="));
}

/// Whether a use reads an enumeration as a number: compared by order or to a literal, used in
/// arithmetic, or converted (`param_x > 0.5`, `int(param_x + 0.5)`, `param_x == 1`, `float(X_Y)`).
bool as_number(const Use& u) {
  const char next = u.after.empty() ? ' ' : u.after[0];
  bool literal_after = false;  // == 1, != 0.0
  if (u.after.starts_with("==") || u.after.starts_with("!=")) {
    const std::size_t operand = u.after.find_first_not_of(' ', 2);
    literal_after = operand != std::string::npos &&
                    (std::isdigit(static_cast<unsigned char>(u.after[operand])) || u.after[operand] == '.');
  }
  return std::string("<>+-*/%").find(next) != std::string::npos || literal_after || u.before.ends_with("int(") ||
         u.before.ends_with("float(") || u.before.ends_with("bool(");
}

}  // namespace

TEST(GpuContract, NoShaderRestatesWhatIsGenerated) {
  // The records, the kinds' codes, the material kinds' parameters, the tables' constants and the
  // methods' choices live only in generated/*.glsl: a hand copy in a shader file would drift from
  // the C++ side unseen.
  std::vector<std::string> generated_only = {"struct LightData", "struct MaterialData", "struct FrameData",
                                             "#define LIGHT_KIND_COUNT", ".kind_params."};
  for (const auto& [name, value] : contract_defines()) generated_only.push_back("#define " + name + " ");
  std::vector<std::string> declared_only_there;  // never declared by hand, as a define or a const
  for (const auto& t : all_tables())
    for (const TableConstant& c : t.glsl_constants) declared_only_there.push_back(c.name);
  std::vector<std::string> choice_names;  // CHOICE of every <PARAM>_<CHOICE>
  for (const ParamDecl* p : enumerations())
    for (const std::string& c : p->choices) {
      declared_only_there.push_back(choice_define(p->name, c));
      choice_names.push_back(choice_define(p->name, c).substr(p->name.size() + 1));
    }
  int files = 0;
  for (const std::string& path : shaders().paths()) {
    if (path.starts_with("generated/")) continue;
    const std::string text = without_comments(shaders().source(path));
    for (const std::string& s : generated_only) EXPECT_EQ(text.find(s), std::string::npos) << path << " has " << s;
    for (const std::string& name : declared_only_there)
      for (const Use& u : uses_of(text, name))
        EXPECT_FALSE(declares(u)) << path << " declares " << name << ", which the generated contract defines";
    for (const ParamDecl* p : enumerations()) {
      for (const Use& u : uses_of(text, "param_" + p->name))
        EXPECT_FALSE(as_number(u)) << path << " reads the enumeration param_" << p->name << " as a number (param_"
                                   << p->name << " " << u.after << "...): compare it with its choices' defines ("
                                   << p->allowed() << ")";
      for (const std::string& c : p->choices)
        for (const Use& u : uses_of(text, choice_define(p->name, c)))
          EXPECT_FALSE(u.before.ends_with("float(")) << path << " converts " << choice_define(p->name, c);
    }
    // A hand-written integer constant named like a choice (REMAINING_LOGNORMAL, COVERAGE_LENS):
    // the choice's generated define is the one to use.
    for (std::size_t at = text.find_first_of("#c"); at != std::string::npos; at = text.find_first_of("#c", at + 1)) {
      std::string name;
      if (text.compare(at, 8, "#define ") == 0) {
        std::size_t e = at + 8;
        while (e < text.size() && identifier_char(text[e])) name += text[e++];
      } else if (text.compare(at, 10, "const int ") == 0 && (at == 0 || !identifier_char(text[at - 1]))) {
        std::size_t e = at + 10;
        while (e < text.size() && identifier_char(text[e])) name += text[e++];
      }
      for (const std::string& c : choice_names)
        EXPECT_FALSE(name.size() > c.size() && name.ends_with("_" + c))
            << path << " defines " << name << ", named like a method's choice " << c
            << ": use that enumeration's generated define, or name the constant for what it is";
    }
    ++files;
  }
  EXPECT_GT(files, 50);
}

TEST(GpuContract, TheScanFindsTheHandCopiesItRefuses) {
  // The checks above on the hand copies this project once had.
  EXPECT_TRUE(declares(uses_of("const int GLINT_LEVELS = 16;", "GLINT_LEVELS")[0]));
  EXPECT_TRUE(declares(uses_of("#define AREA_LIGHTS_LTC 1", "AREA_LIGHTS_LTC")[0]));
  EXPECT_FALSE(declares(uses_of("if (a == AREA_LIGHTS_LTC)", "AREA_LIGHTS_LTC")[0]));
  EXPECT_FALSE(declares(uses_of("if (AREA_LIGHTS_LTC == a)", "AREA_LIGHTS_LTC")[0]));
  EXPECT_TRUE(as_number(uses_of("if (param_lean > 0.5)", "param_lean")[0]));
  EXPECT_TRUE(as_number(uses_of("int(param_area + 0.5)", "param_area")[0]));
  EXPECT_TRUE(as_number(uses_of("x = float(param_area);", "param_area")[0]));
  EXPECT_TRUE(as_number(uses_of("param_area == 2 ? a : b", "param_area")[0]));
  EXPECT_FALSE(as_number(uses_of("param_area == AREA_LENS ? a : b", "param_area")[0]));
  EXPECT_FALSE(as_number(uses_of("f(s, param_area, x)", "param_area")[0]));
  EXPECT_TRUE(uses_of("param_leaning > 0.5", "param_lean").empty()) << "whole identifiers only";
}
