// GL device tests: the context, every shader module compiles, and the GLSL BRDF agrees with
// independent closed forms and integrals computed here in C++.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "builtin_scene_programs.hpp"
#include "core/error.hpp"
#include "gl_fixture.hpp"
#include "glsl/glslang_validator.hpp"
#include "render/renderer.hpp"

using namespace glintlab;
using namespace glintlab::test;

TEST(GlContext, IsOpenGL45Core) {
  const auto info = context().info();
  EXPECT_GE(epoxy_gl_version(), 45) << info.version;
  EXPECT_FALSE(info.renderer.empty());
}

namespace {

struct ShadingModule {
  std::string path;
  bool rendered_on_builtin_scenes;  // by Images/EveryMethodOnBuiltinScene (builtin_scene_programs.hpp)
};

// Every method's module and the passes that take the $METHOD slot.
std::vector<ShadingModule> every_shading_module() {
  std::vector<ShadingModule> modules{{kReferenceModule, true}, {"passes/unshaded.glsl", false}};
  for (const auto& m : all_methods()) {
    EXPECT_TRUE(shaders().exists(m.module_path())) << m.id;
    modules.push_back({method_program_module(shaders(), m), true});
  }
  return modules;
}

/// Two lights of each kind not in `except` (the index ranges of a light buffer sorted by kind).
LightRanges two_lights_of_every_kind_but(const std::set<int>& except) {
  LightRanges ranges;
  int next = 0;
  for (int k = 0; k < static_cast<int>(all_light_kinds().size()); ++k) {
    const int count = except.contains(k) ? 0 : 2;
    ranges.emplace_back(next, next + count);
    next += count;
  }
  return ranges;
}

std::string kind_names(const LightRanges& ranges) {
  std::string names;
  for (std::size_t k = 0; k < ranges.size(); ++k)
    if (ranges[k].x < ranges[k].y) names += (names.empty() ? "" : ", ") + all_light_kinds()[k].id;
  return names;
}

std::string variant_label(const std::string& module, MaterialVariant v, const LightRanges& lights) {
  return module + ", " + all_material_kinds()[static_cast<std::size_t>(v.kind)].id + " material" +
         (v.normal_map ? " with a normal map" : "") + (v.wang_tiles ? " of Wang tiles" : "") +
         (v.textures ? ", textured" : "") + "; lights " + kind_names(lights);
}

/// The forward program of `module` in variant `v` with `lights`: its fragment stage valid GLSL
/// (glslang; the vertex stage does not depend on the variant: checked once, below).
void expect_compiles(GlslangValidator& glslang, const std::string& module, MaterialVariant v, const LightRanges& lights) {
  glslang.expect_valid(shaders(), "passes/forward.frag", forward_variant(module, lights, v), variant_label(module, v, lights));
}

/// Checks every module in variant `v` (and its normal-mapped twin) with two lights of each kind
/// that Images/EveryMethodOnBuiltinScene does not draw it with (all of them for a variant no
/// built-in scene has): together the two cover each module with every light kind in every
/// variant, the drawn ones compiled by the driver, these by glslang. Returns the number checked.
int expect_every_module_compiles_in(MaterialVariant v) {
  GlslangValidator glslang;
  for (const auto& module : every_shading_module())
    for (bool normal_map : {false, true}) {
      if (all_material_kinds()[static_cast<std::size_t>(v.kind)].requires_normal_map && !normal_map) continue;
      v.normal_map = normal_map;
      std::set<int> on_builtin_scenes;
      if (module.rendered_on_builtin_scenes)
        if (const auto& kinds = builtin_scene_light_kinds(); kinds.contains(v)) on_builtin_scenes = kinds.at(v);
      if (on_builtin_scenes.size() == all_light_kinds().size()) continue;
      expect_compiles(glslang, module.path, v, two_lights_of_every_kind_but(on_builtin_scenes));
    }
  return glslang.count();
}

}  // namespace

// Every module in every material variant with every light kind, one material kind per test, less
// what the built-in scene tests draw (builtin_scene_programs.hpp), validated by glslang
// (glsl/glslang_validator.hpp). Each test checks at least the unshaded pass.
class EveryMethodAndPassCompiles : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethodAndPassCompiles, ForMaterialKind) {
  ASSERT_TRUE(GlslangValidator::available()) << "glslangValidator (Debian's glslang-tools; tools/install-deps.sh)";
  const MaterialKind& kind = find_material_kind(GetParam());
  EXPECT_GT(expect_every_module_compiles_in({kind.code(), false, false}), 0);
  if (&kind != &default_material_kind()) return;
  // The passes that take no module, by the driver (they are small).
  EXPECT_NO_THROW(shaders().graphics("passes/forward.vert", "passes/emitter.frag"));
  EXPECT_NO_THROW(shaders().graphics("passes/background.vert", "passes/background.frag"));
  EXPECT_NO_THROW(shaders().compute("passes/downsample.comp"));
  GlslangValidator glslang;
  glslang.expect_valid(shaders(), "passes/forward.vert", forward_variant(kReferenceModule, two_lights_of_every_kind_but({}), {}),
                       "the forward pass's vertex stage");
}

INSTANTIATE_TEST_SUITE_P(Shaders, EveryMethodAndPassCompiles, ::testing::ValuesIn(material_kind_ids()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

// Textured materials (glTF's, of the default kind: the other kinds' parameters are constants).
TEST(Shaders, EveryMethodAndPassCompilesForTextures) {
  EXPECT_GT(expect_every_module_compiles_in({default_material_kind().code(), false, true}), 0);
}

// A normal map of Wang tiles (MATERIAL_WANG_TILES; only normal-map-glints materials may have one).
TEST(Shaders, EveryMethodAndPassCompilesForWangTiles) {
  ASSERT_TRUE(GlslangValidator::available()) << "glslangValidator (Debian's glslang-tools; tools/install-deps.sh)";
  EXPECT_GT(expect_every_module_compiles_in({.kind = find_material_kind("normal-map-glints").code(), .wang_tiles = true}), 0);
}

// Every other choice of each method's compile-time parameters (ParamDecl::compile_time), the
// others at their defaults, in the plain material variant: the choices select code that does not
// depend on the material's variant, which EveryMethodAndPassCompiles covers at the defaults.
TEST(Shaders, EveryChoiceOfACompileTimeParameterCompiles) {
  ASSERT_TRUE(GlslangValidator::available()) << "glslangValidator (Debian's glslang-tools; tools/install-deps.sh)";
  GlslangValidator glslang;
  for (const auto& m : all_methods())
    for (const auto& p : m.params)
      for (std::size_t c = 0; p.compile_time && c < p.choices.size(); ++c) {
        if (c == static_cast<std::size_t>(p.default_value)) continue;
        expect_compiles(glslang, method_program_module(shaders(), m, {{p.name, static_cast<float>(c)}}), {},
                        two_lights_of_every_kind_but({}));
      }
  EXPECT_GT(glslang.count(), 0);
}

// The validator can fail: a program that calls what no file defines.
TEST(Shaders, GlslangRejectsAnUndefinedFunction) {
  ASSERT_TRUE(GlslangValidator::available());
  shaders().add_source("test/broken-for-glslang.comp", "layout(local_size_x = 1) in;\nvoid main() { undefined_call(); }\n");
  GlslangValidator glslang;
  EXPECT_NONFATAL_FAILURE(glslang.expect_valid(shaders(), "test/broken-for-glslang.comp", {}, "broken"),
                          "undefined_call");
}

TEST(Shaders, CompileErrorsNameTheFile) {
  shaders().add_source("test/broken.comp", "layout(local_size_x = 1) in;\nvoid main() { undefined_call(); }\n");
  try {
    shaders().compute("test/broken.comp");
    FAIL();
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find("test/broken.comp"), std::string::npos) << e.what();
  }
}

namespace {

// Independent C++ GGX (Walter et al. 2007; Heitz 2014) for the comparison.
double ggx_d(glm::dvec3 h, double ax, double ay) {
  if (h.z <= 0) return 0;
  const double e = h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z;
  return 1.0 / (M_PI * ax * ay * e * e);
}
double ggx_lambda(glm::dvec3 w, double ax, double ay) {
  return 0.5 * (-1.0 + std::sqrt(1.0 + (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z)));
}

const char* kBrdf = "#include \"core/brdf.glsl\"\n";

/// Midpoint quadrature of f(h) over the hemisphere in (cos theta, phi).
std::vector<glm::vec4> hemisphere_grid(int n) {
  std::vector<glm::vec4> dirs;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double mu = (i + 0.5) / n, phi = 2 * M_PI * (j + 0.5) / n, s = std::sqrt(1 - mu * mu);
      dirs.emplace_back(s * std::cos(phi), s * std::sin(phi), mu, 0.0f);
    }
  return dirs;
}

}  // namespace

TEST(Brdf, NdfsIntegrateToOneOverTheProjectedHemisphere) {
  const int n = 1024;
  const auto dirs = hemisphere_grid(n);
  for (const glm::vec2 alpha : {glm::vec2(0.3f), glm::vec2(0.15f, 0.6f), glm::vec2(0.8f)})
    for (int kind : {0, 1}) {
      const std::vector<glm::vec4> params(dirs.size(), glm::vec4(alpha, kind, 0));
      const auto d = evaluate_glsl(kBrdf, "vec4 evaluate(vec4 h, vec4 p) { return vec4(ndf(int(p.z), h.xyz, p.xy) * h.z); }",
                                   dirs, params);
      double sum = 0;
      for (const auto& v : d) sum += v.x;
      sum *= 2 * M_PI / (static_cast<double>(n) * n);  // d(omega) = d(mu) d(phi)
      EXPECT_NEAR(sum, 1.0, 0.01) << "kind " << kind << " alpha " << alpha.x << "," << alpha.y;
    }
}

TEST(Brdf, SmithMaskingIsConsistentWithTheNdf) {
  // The visible-normal identity: integral of G1(v) max(0, v.h) D(h) dh = v.z (Heitz 2014, eq. 38).
  const int n = 1024;
  const auto dirs = hemisphere_grid(n);
  for (int kind : {0, 1})
    for (float theta : {0.3f, 1.0f, 1.4f}) {
      const glm::vec4 v(std::sin(theta), 0.0f, std::cos(theta), static_cast<float>(kind));
      const std::vector<glm::vec4> params(dirs.size(), v);
      const auto r = evaluate_glsl(kBrdf,
                                   "vec4 evaluate(vec4 h, vec4 v) { vec2 a = vec2(0.2, 0.5); int k = int(v.w);\n"
                                   "  return vec4(smithG1(k, v.xyz, a) * max(0.0, dot(v.xyz, h.xyz)) * ndf(k, h.xyz, a)); }",
                                   dirs, params);
      double sum = 0;
      for (const auto& x : r) sum += x.x;
      sum *= 2 * M_PI / (static_cast<double>(n) * n);
      // Beckmann's Lambda is Walter's rational fit (< 0.35% error), GGX's is exact.
      EXPECT_NEAR(sum / v.z, 1.0, kind == 0 ? 0.01 : 0.02) << "kind " << kind << " theta " << theta;
    }
}

TEST(Brdf, GgxSpecularMatchesAnIndependentImplementation) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> wo, wi;
  for (int i = 0; i < 4096; ++i) {
    auto dir = [&] {
      const float mu = 0.02f + 0.98f * u(rng), phi = 6.2831853f * u(rng), s = std::sqrt(1 - mu * mu);
      return glm::vec3(s * std::cos(phi), s * std::sin(phi), mu);
    };
    wo.emplace_back(dir(), 0.01f + 0.99f * u(rng));  // w: alpha_x
    wi.emplace_back(dir(), 0.01f + 0.99f * u(rng));  // w: alpha_y
  }
  const auto gpu = evaluate_glsl(kBrdf,
                                 "vec4 evaluate(vec4 o, vec4 i) { return vec4(specularCos(0, o.xyz, i.xyz, vec2(o.w, i.w), vec3(0.04, 0.5, 1.0)), 0.0); }",
                                 wo, wi);
  for (std::size_t k = 0; k < wo.size(); ++k) {
    const glm::dvec3 o(wo[k]), i(wi[k]);
    const double ax = wo[k].w, ay = wi[k].w;
    const glm::dvec3 h = glm::normalize(o + i);
    const double g = 1.0 / (1.0 + ggx_lambda(o, ax, ay) + ggx_lambda(i, ax, ay));
    const double f = 0.5 + 0.5 * std::pow(1.0 - glm::dot(o, h), 5.0);  // Schlick with F0 = 0.5
    const double expected = f * ggx_d(h, ax, ay) * g / (4.0 * o.z);
    EXPECT_NEAR(gpu[k].y, expected, 2e-4 * expected + 1e-6) << k;
  }
}
