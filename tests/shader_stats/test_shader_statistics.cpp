// The static counts of docs/shader-statistics.md: the SPIR-V analysis on programs written here,
// whose answers are known (it must find a dynamically indexed local array, and must not count
// one that unrolling makes constant), and every method's default program without a dynamically
// indexed local array (local memory on a GPU).
#include <gtest/gtest.h>

#include <cctype>

#include "core/error.hpp"
#include "render/shader_contract.hpp"
#include "shading/registry.hpp"
#include "shader_stats/program_statistics.hpp"

using namespace glintlab;

namespace {

/// A fragment stage around `body` (main's), with an SSBO, a texture and a uniform bound.
ShaderStatistics statistics_of_body(const std::string& declarations, const std::string& body) {
  return shader_statistics_of("#version 450 core\n"
                              "layout(std430, binding = 0) readonly buffer Values { float values[]; };\n"
                              "layout(binding = 0) uniform sampler2D uMap;\n"
                              "uniform int uCount;\n"
                              "in vec2 vUV;\n"
                              "layout(location = 0) out vec4 outColour;\n" +
                              declarations + "\nvoid main() {\n" + body + "\n}\n");
}

}  // namespace

TEST(ShaderStatistics, FindsAnArrayIndexedAtRunTime) {
  const ShaderStatistics s = statistics_of_body("", R"(
    float a[4] = float[4](vUV.x, vUV.y, 2.0 * vUV.x, 3.0);
    int i = int(vUV.x * 4.0) & 3;
    outColour = vec4(a[i]);)");
  EXPECT_EQ(s.dynamic_local_array_accesses(), 1);
  ASSERT_EQ(s.dynamic_local_arrays.size(), 1u);
  EXPECT_EQ(s.dynamic_local_arrays.begin()->first.substr(0, 8), "float[4]");
}

TEST(ShaderStatistics, ALoopOfConstantCountIndexesByConstantsOnceUnrolled) {
  const ShaderStatistics unrolled = statistics_of_body("", R"(
    float a[4];
    for (int i = 0; i < 4; ++i) a[i] = vUV.x * float(i + 1);
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += a[i] * a[3 - i];
    outColour = vec4(sum);)");
  EXPECT_EQ(unrolled.dynamic_local_array_accesses(), 0);
  EXPECT_EQ(unrolled.loops, 0);
  // The same loop with a count known only at run time keeps the array in local memory.
  const ShaderStatistics rolled = statistics_of_body("", R"(
    float a[4];
    for (int i = 0; i < 4; ++i) a[i] = vUV.x * float(i + 1);
    float sum = 0.0;
    for (int i = 0; i < min(uCount, 4); ++i) sum += a[i];
    outColour = vec4(sum);)");
  EXPECT_GT(rolled.dynamic_local_array_accesses(), 0);
  EXPECT_EQ(rolled.loops, 1);
}

TEST(ShaderStatistics, CountsFetchesLoadsAndTranscendentals) {
  const ShaderStatistics s = statistics_of_body("", R"(
    vec4 t = texture(uMap, vUV) + textureLod(uMap, vUV * 2.0, 1.0);
    float v = values[int(vUV.x * 8.0)] + values[int(vUV.y * 8.0)] + values[3];
    outColour = t * v + vec4(sin(vUV.x) + exp(vUV.y) + sqrt(v));)");
  EXPECT_EQ(s.texture_fetches, 2);
  EXPECT_EQ(s.buffer_loads, 3);
  EXPECT_EQ(s.transcendentals, 3);
  EXPECT_EQ(s.dynamic_local_array_accesses(), 0);  // a buffer indexed at run time is no local array
}

TEST(ShaderStatistics, RefusesInvalidGlsl) {
  EXPECT_THROW(statistics_of_body("", "outColour = undefined_function();"), RuntimeFailure);
}

// Each method at its defaults on its own material kinds, and the reference: in the hardware
// profile (GPUs, where an array indexed at run time lives in local memory), with one light of
// every kind, no function-local or private array is indexed at run time once the loops with
// constant counts are unrolled. One test per row of docs/shader-statistics.md's tables, so that
// ctest spreads them over the cores.
class DefaultProgram : public ::testing::TestWithParam<int> {};

namespace {
ShaderLibrary& stats_shaders() {
  static ShaderLibrary shaders = [] {
    ShaderLibrary s(DriverProfile::Hardware);
    add_contract_sources(s);
    return s;
  }();
  return shaders;
}
// The rows of the tables, less the plain twins of the normal-mapped rows of methods that treat
// every kind alike: the normal-mapped program holds the plain one's code but for the map's read
// (each program takes seconds to optimise; the docs' tables have both).
const std::vector<ProgramRow>& rows() {
  static const std::vector<ProgramRow> r = [] {
    std::vector<ProgramRow> kept;
    for (const ProgramRow& row : program_rows(stats_shaders())) {
      const MethodDescriptor* method = row.name == "(reference)" ? nullptr : &find_method(row.name);
      if (method && method->material_kinds.empty() && !row.material.normal_map) continue;
      kept.push_back(row);
    }
    return kept;
  }();
  return r;
}
}  // namespace

TEST_P(DefaultProgram, KeepsNoDynamicallyIndexedLocalArray) {
  const ProgramRow& row = rows().at(static_cast<std::size_t>(GetParam()));
  const ShaderStatistics s = shader_statistics_of(
      forward_program_text(stats_shaders(), row.module, row.material, one_light_of_every_kind(), ProgramStage::Fragment));
  std::string arrays;
  for (const auto& [array, count] : s.dynamic_local_arrays) arrays += " " + array + " x" + std::to_string(count);
  EXPECT_EQ(s.dynamic_local_array_accesses(), 0) << row.name << " on " << row.material_label() << ":" << arrays;
  EXPECT_GT(s.operations, 0);
}

INSTANTIATE_TEST_SUITE_P(Methods, DefaultProgram, ::testing::Range(0, static_cast<int>(rows().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           const ProgramRow& row = rows().at(static_cast<std::size_t>(info.param));
                           std::string name = row.name + "_" + row.material_label();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });
