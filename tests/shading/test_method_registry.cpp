// The method extension point: a method is its module and its self-registering descriptor.
// tests/shading/methods/test-gain.{cpp,glsl} add `test-gain` to this binary exactly as a
// contributor adds a method; it is listed, renders, and its parameter reaches the shader.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "gl_fixture.hpp"
#include "shading/method_module.hpp"
#include "shading/registry.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The shader library gets the test method's module as the build embeds shaders/methods/*.glsl.
void add_test_gain_module() {
  if (!shaders().exists("methods/test-gain.glsl"))
    shaders().add_source("methods/test-gain.glsl",
                         read_text(GLINTLAB_SOURCE_DIR "/tests/shading/methods/test-gain.glsl"));
}

/// Glossy sphere on a diffuse plane, a point and a directional light, no visible emitters (they
/// are drawn by another pass, which no method scales).
/// A glossy sphere on a floor under a point and a directional light.
TestScene glossy_scene() {
  return TestScene()
      .film(48, 32)
      .camera({0, 1.5, 4}, {0, 0.3, 0}, 40)
      .material("metal", {{"f0", 0.6}, {"diffuse", 0.2}, {"alpha", 0.15}})
      .material("floor", {{"f0", 0.04}, {"diffuse", 0.5}, {"alpha", 0.4}})
      .sphere("metal", {{"radius", 0.6}, {"translate", {0, 0.6, 0}}})
      .plane("floor", {{"size", 6}})
      .point_light({1, 3, 2}, 8)
      .directional_light({-0.3, -1, -0.5}, 1.5);
}
double sum_of(const Image& image) {
  double sum = 0;
  for (const glm::vec3& p : image.pixels()) sum += double(p.r) + p.g + p.b;
  return sum;
}

bool all_finite(const Image& image) {
  for (const glm::vec3& p : image.pixels())
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

/// Every pixel of `a` equals `factor` times `b`'s, exactly (a power-of-two factor scales exactly).
void expect_scaled(const Image& a, const Image& b, float factor) {
  ASSERT_EQ(a.pixel_count(), b.pixel_count());
  int differing = 0;
  for (std::size_t i = 0; i < a.pixel_count(); ++i)
    if (a.pixels()[i] != factor * b.pixels()[i]) ++differing;
  EXPECT_EQ(differing, 0) << "pixels not exactly " << factor << " times conventional's";
}

/// The message of the RuntimeFailure that rendering `method` throws ("" if none).
std::string render_failure(SceneFixture& f, const MethodDescriptor& method) {
  try {
    f.renderer->render(method, resolve_params(method, {}), f.scene.camera, f.scene.film.width, f.scene.film.height);
  } catch (const RuntimeFailure& e) {
    return e.what();
  }
  return "";
}

MethodDescriptor descriptor(const std::string& id, std::vector<ParamDecl> params) {
  return {.id = id, .title = id, .citation = "test", .summary = "test", .params = std::move(params), .tables = {}};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(MethodRegistry, ListsTheBuiltInMethodsInTheirDeclaredOrderThenTheTestMethod) {
  const std::vector<std::string> expected{"conventional", "toksvig",        "vlachos",      "kaplanyan-beckmann",
                                          "kaplanyan-rect", "kaplanyan-ggx", "tokuyoshi",    "lean",
                                          "podee",        "chermain2020",   "chermain2021", "deliot2023",
                                          "kneiphof2024", "kneiphof2025",   "yan2016",      "deng2022",     "kemppinen2025", "test-gain"};
  std::vector<std::string> ids;
  for (const auto& m : all_methods()) ids.push_back(m.id);
  EXPECT_EQ(ids, expected);
  EXPECT_EQ(find_method("test-gain").params.at(0).name, "gain");
  EXPECT_EQ(parse_method_list("all").back()->id, "test-gain");
}

TEST(MethodRegistry, AMethodAddedAsTwoFilesRendersAsItsModuleSays) {
  add_test_gain_module();
  SceneFixture f(glossy_scene());
  const Frame conventional = f.method("conventional");
  const Frame added = f.method("test-gain");  // gain = 1 by default
  EXPECT_TRUE(all_finite(added.total));
  EXPECT_GT(sum_of(added.specular), 0.0);
  EXPECT_GT(sum_of(added.total), sum_of(added.specular));  // diffuse too
  expect_scaled(added.total, conventional.total, 1.0f);
  expect_scaled(added.specular, conventional.specular, 1.0f);
}

TEST(MethodRegistry, ParameterValuesReachTheShader) {
  add_test_gain_module();
  SceneFixture f(glossy_scene());
  const Frame conventional = f.method("conventional");
  const Frame doubled = f.method("test-gain", {{"gain", "2"}});
  expect_scaled(doubled.total, conventional.total, 2.0f);
  expect_scaled(doubled.specular, conventional.specular, 2.0f);
  EXPECT_EQ(sum_of(f.method("test-gain", {{"gain", "0"}}).total), 0.0);
  // An enumeration: a `uniform int` set to the choice's index, equal to its generated define.
  const Frame specular_only = f.method("test-gain", {{"gain", "2"}, {"terms", "specular"}});
  expect_scaled(specular_only.specular, conventional.specular, 2.0f);
  const double diffuse = sum_of(conventional.total) - sum_of(conventional.specular);
  EXPECT_NEAR(sum_of(specular_only.total) - sum_of(specular_only.specular), diffuse, 1e-4 * diffuse);
  EXPECT_GT(diffuse, 0.1 * sum_of(conventional.total));
}

TEST(MethodRegistry, ADeclaredParameterTheModuleNeverReadsIsAnErrorNamingIt) {
  shaders().add_source("methods/test-unused.glsl", R"(
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"
// param_unused is named here only in a comment: that is not a use.
void prepareSurface(inout Surface s) { s.alpha *= param_used; }
Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, materialLobe(s)); }
)");
  SceneFixture f(glossy_scene());
  const std::string message =
      render_failure(f, descriptor("test-unused", {{"used", 1, 0, 1, "read"}, {"unused", 1, 0, 1, "never read"}}));
  EXPECT_TRUE(contains(message, "method 'test-unused'")) << message;
  EXPECT_TRUE(contains(message, "parameter 'unused'")) << message;
  EXPECT_TRUE(contains(message, "shaders/methods/test-unused.glsl")) << message;
}

TEST(MethodRegistry, AParameterTheModuleReadsButDoesNotDeclareIsAnErrorNamingIt) {
  shaders().add_source("methods/test-undeclared.glsl", R"(
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"
void prepareSurface(inout Surface s) { s.alpha *= param_missing; }
Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, materialLobe(s)); }
)");
  SceneFixture f(glossy_scene());
  const std::string message = render_failure(f, descriptor("test-undeclared", {}));
  EXPECT_TRUE(contains(message, "method 'test-undeclared'")) << message;
  EXPECT_TRUE(contains(message, "param_missing")) << message;
  EXPECT_TRUE(contains(message, "declared: none")) << message;
}

TEST(MethodModule, DeclaresEachParameterThenIncludesTheModule) {
  const std::string source =
      generated_module_source(descriptor("m", {{"a", 0, 0, 1, ""}, {"b_2", 0, 0, 1, ""}}), "x = param_a + param_b_2;");
  const auto a = source.find("uniform float param_a;\n"), b = source.find("uniform float param_b_2;\n"),
             include = source.find("#include \"methods/m.glsl\"\n");
  EXPECT_TRUE(a < b && b < include && include != std::string::npos) << source;
  EXPECT_EQ(generated_module_path(descriptor("m", {})), "generated/methods/m.glsl");
}

TEST(MethodModule, EnumerationsAreIntsTheirChoicesIndices) {
  ParamDecl picked{"picked", 0, 0, 2, "", {"first", "second-one", "third"}};
  ParamDecl fixed = picked;
  fixed.name = "fixed";
  fixed.compile_time = true;
  const MethodDescriptor m = descriptor("m", {picked, fixed});
  const std::string source = generated_module_source(m, "x = param_picked == param_fixed;", {{"fixed", 1.0f}});
  EXPECT_TRUE(contains(source, "uniform int param_picked;\n")) << source;
  EXPECT_TRUE(contains(source, "const int param_fixed = 1;  // FIXED_SECOND_ONE\n")) << source;
  EXPECT_EQ(generated_module_path(m, {{"fixed", 2.0f}}), "generated/methods/m.fixed-third.glsl");
}

TEST(MethodModule, HostOnlyParametersAreHiddenUnlessTheySpecialiseTheModule) {
  // A host-only setting never reaches GLSL (reading it is an error); one that specialises the
  // module (deng2022's rank and grid) is a constant of its value, each value its own program.
  ParamDecl hidden{"hidden", 4, 1, 8, ""};
  hidden.host_only = hidden.integer = true;
  ParamDecl shape = hidden;
  shape.name = "shape";
  shape.specialises = true;
  const MethodDescriptor m = descriptor("m", {hidden, shape});
  const std::string source = generated_module_source(m, "x = param_shape;", {{"shape", 6.0f}});
  EXPECT_TRUE(contains(source, "const int param_shape = 6;\n")) << source;
  EXPECT_FALSE(contains(source, "param_hidden")) << source;
  EXPECT_EQ(generated_module_path(m, {{"shape", 6.0f}}), "generated/methods/m.shape-6.glsl");
  EXPECT_EQ(generated_module_path(m), "generated/methods/m.shape-4.glsl");
  EXPECT_THROW(generated_module_source(m, "x = param_shape + param_hidden;"), RuntimeFailure);
  EXPECT_THROW(generated_module_source(m, "x = 1;"), RuntimeFailure) << "a specialising parameter never read";
  // deng2022's compile its pyramid's shape in.
  const MethodDescriptor& deng = find_method("deng2022");
  EXPECT_TRUE(contains(generated_module_path(deng, {{"rank", 8.0f}}), ".rank-8.")) << generated_module_path(deng);
  EXPECT_TRUE(contains(generated_module_path(deng), ".ndf_resolution-64.block_size-16.")) << generated_module_path(deng);
}

TEST(MethodRegistry, ChoiceDefinesAreTheParameterAndChoiceInUpperSnakeCase) {
  EXPECT_EQ(choice_define("area_lights", "representative-point"), "AREA_LIGHTS_REPRESENTATIVE_POINT");
  EXPECT_EQ(choice_define("remaining_count", "lognormal"), "REMAINING_COUNT_LOGNORMAL");
  EXPECT_EQ(choice_define("lean", "on"), "LEAN_ON");
  EXPECT_EQ(choice_define("subdivision", "2x2"), "SUBDIVISION_2X2");
  EXPECT_EQ(choice_define("elements_per_texel", "1"), "ELEMENTS_PER_TEXEL_1");
  // The registered methods' choices, each name once, valued by their index.
  const auto defines = enumeration_defines(all_methods());
  const auto value = [&](const std::string& name) {
    const auto it = std::find_if(defines.begin(), defines.end(), [&](const auto& d) { return d.first == name; });
    return it == defines.end() ? std::string("absent") : it->second;
  };
  EXPECT_EQ(value("AREA_LIGHTS_REPRESENTATIVE_POINT"), "0");
  EXPECT_EQ(value("AREA_LIGHTS_LTC"), "1");
  EXPECT_EQ(value("TERMS_SPECULAR"), "1") << "test-gain's, registered in this binary";
  EXPECT_EQ(std::count_if(defines.begin(), defines.end(), [](const auto& d) { return d.first == "AREA_LIGHTS_LTC"; }),
            1);
}

TEST(MethodModule, AModuleDeclaringItsOwnParameterUniformIsAnError) {
  try {
    generated_module_source(descriptor("m", {{"a", 0, 0, 1, ""}}),
                            "uniform float param_a;\nfloat f() { return param_a; }");
    FAIL();
  } catch (const RuntimeFailure& e) {
    EXPECT_TRUE(contains(e.what(), "declares the uniform param_a itself")) << e.what();
  }
}

TEST(MethodModule, ParametersAreWholeIdentifiers) {
  // param_lean is not read by a module that reads only param_leaning.
  EXPECT_THROW(generated_module_source(descriptor("m", {{"lean", 0, 0, 1, ""}, {"leaning", 0, 0, 1, ""}}),
                                       "float f() { return param_leaning; } /* param_lean */"),
               RuntimeFailure);
  EXPECT_NO_THROW(generated_module_source(descriptor("m", {{"lean", 0, 0, 1, ""}}), "bool b = param_lean>0.5;"));
}

namespace {
MethodDescriptor first() { return descriptor("first", {}); }
MethodDescriptor second() { return descriptor("second", {}); }
MethodDescriptor first_again() { return descriptor("first", {}); }
MethodDescriptor bad_param() { return descriptor("bad", {{"not an identifier", 0, 0, 1, ""}}); }
MethodDescriptor bad_default() { return descriptor("bad", {{"p", 2, 0, 1, ""}}); }
MethodDescriptor bad_choice() { return descriptor("bad", {{"p", 0, 0, 1, "", {"ok", "Not OK"}}}); }
MethodDescriptor one_define() { return descriptor("bad", {{"p", 0, 0, 1, "", {"a-b", "a_b"}}}); }
MethodDescriptor lean_on_off() { return descriptor("first", {{"lean", 0, 0, 1, "", {"off", "on"}}}); }
MethodDescriptor lean_other() { return descriptor("second", {{"lean", 0, 0, 2, "", {"off", "on", "more"}}}); }
MethodDescriptor lean_number() { return descriptor("second", {{"lean", 0, 0, 1, ""}}); }
MethodDescriptor lean_same() { return descriptor("second", {{"lean", 1, 0, 1, "", {"off", "on"}}}); }
MethodDescriptor lean_x() { return descriptor("second", {{"lean_x", 0, 0, 1, "", {"y", "z"}}}); }
MethodDescriptor lean_collides() { return descriptor("third", {{"lean", 0, 0, 1, "", {"x_y", "w"}}}); }

std::string ordering_failure(const std::vector<MethodRegistration>& registrations) {
  try {
    ordered_methods(registrations);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(MethodRegistry, OrdersByListingKeyNotByRegistration) {
  const auto methods = ordered_methods({{&second, 20, "b.cpp"}, {&first, 10, "a.cpp"}});
  ASSERT_EQ(methods.size(), 2u);
  EXPECT_EQ(methods[0].id, "first");
  EXPECT_EQ(methods[1].id, "second");
}

TEST(MethodRegistry, ARepeatedIdOrListingKeyIsAnErrorNamingBothFiles) {
  const std::string id = ordering_failure({{&first, 10, "src/a.cpp"}, {&first_again, 20, "src/b.cpp"}});
  EXPECT_TRUE(contains(id, "'first' is registered twice, by a.cpp and b.cpp")) << id;
  const std::string key = ordering_failure({{&first, 10, "a.cpp"}, {&second, 10, "b.cpp"}});
  EXPECT_TRUE(contains(key, "share the listing key 10")) << key;
}

TEST(MethodRegistry, AnInvalidDeclarationIsAnErrorNamingTheMethod) {
  EXPECT_TRUE(
      contains(ordering_failure({{&bad_param, 1, "bad.cpp"}}), "'not an identifier' is not a GLSL identifier"));
  EXPECT_TRUE(contains(ordering_failure({{&bad_default, 1, "bad.cpp"}}), "method 'bad' (bad.cpp)"));
  EXPECT_TRUE(contains(ordering_failure({{&bad_choice, 1, "bad.cpp"}}), "has the choice 'Not OK'"));
  EXPECT_TRUE(contains(ordering_failure({{&one_define, 1, "bad.cpp"}}), "which are one GLSL define, P_A_B"));
}

TEST(MethodRegistry, AnEnumerationHasTheSameChoicesInEveryMethod) {
  // Its GLSL defines are shared, so that code several methods use can test a choice.
  for (auto other : {&lean_other, &lean_number}) {
    const std::string message = ordering_failure({{&lean_on_off, 10, "src/a.cpp"}, {other, 20, "src/b.cpp"}});
    EXPECT_TRUE(contains(message, "methods 'first' (a.cpp) and 'second' (b.cpp) both declare the parameter 'lean'"))
        << message;
  }
  EXPECT_EQ(ordering_failure({{&lean_on_off, 10, "a.cpp"}, {&lean_same, 20, "b.cpp"}}), "") << "defaults may differ";
  // lean_x = y and lean = x_y are both LEAN_X_Y.
  const std::string collision = ordering_failure({{&lean_x, 10, "a.cpp"}, {&lean_collides, 20, "c.cpp"}});
  EXPECT_TRUE(contains(collision, "are both the GLSL define LEAN_X_Y")) << collision;
  EXPECT_TRUE(contains(collision, "'third' (c.cpp)") && contains(collision, "'second' (a.cpp)")) << collision;
}
