// Precomputed tables on the GPU (src/tables): the registry, units and their GLSL defines,
// the upload against its declared size, and who makes a table resident: the scene's glinty
// materials, and a method that declares it.
#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"

#include "gl_fixture.hpp"
#include "tables/gpu_tables.hpp"
#include "shading/registry.hpp"

namespace glintlab {
namespace {

using test::context;
using test::SceneFixture;

TEST(Tables, EveryTableAMethodDeclaresIsRegistered) {
  for (const auto& m : all_methods())
    for (const auto& id : m.tables) EXPECT_NO_THROW((void)find_table(id)) << m.id << " declares '" << id << "'";
  EXPECT_EQ(find_method("chermain2020").tables, std::vector<std::string>{"glint-dictionary"});
  EXPECT_EQ(find_method("chermain2021").tables, std::vector<std::string>{"glint-dictionary"});
  try {
    (void)find_table("no-such-table");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("glint-dictionary"), std::string::npos) << e.what();
  }
}

TEST(Tables, EachHasItsOwnUnitAboveTheMaterialsTexturesAndAGlslDefine) {
  GLint max_units = 0;
  context();
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &max_units);
  std::set<int> units;
  std::set<std::string> ids;
  for (const auto& t : all_tables()) {
    EXPECT_GE(t.unit, kFirstTableUnit) << t.source.id;
    EXPECT_LT(t.unit, max_units) << t.source.id;
    EXPECT_TRUE(units.insert(t.unit).second) << t.source.id << ": unit " << t.unit << " is taken";
    EXPECT_TRUE(ids.insert(t.source.id).second) << t.source.id << " is registered twice";
    EXPECT_FALSE(t.source.settings.empty()) << t.source.id << ": the settings key the cache";
    EXPECT_FALSE(t.sampler.empty()) << t.source.id;
  }
  EXPECT_EQ(table_define("glint-dictionary"), "TABLE_UNIT_GLINT_DICTIONARY");
  const ShaderDefines defines = table_defines();
  EXPECT_NE(std::find(defines.begin(), defines.end(),
                      std::pair<std::string, std::string>{"TABLE_UNIT_GLINT_DICTIONARY",
                                                          std::to_string(find_table("glint-dictionary").unit)}),
            defines.end());
}

TEST(Tables, TheGlslSamplerReadsTheUnitTheRegistryBindsItTo) {
  // The define reaches GLSL: the sampler's binding, as the linked program reports it.
  const auto r = test::evaluate_glsl("#include \"glints/chermain/dictionary.glsl\"",
                                     "vec4 evaluate(vec4 a, vec4 b) { return vec4(TABLE_UNIT_GLINT_DICTIONARY); }",
                                     {glm::vec4(0)}, {glm::vec4(0)});
  EXPECT_EQ(r[0].x, static_cast<float>(find_table("glint-dictionary").unit));
}

TEST(Tables, TheUploadHasTheSizeTheTableDeclares) {
  context();
  for (const auto& t : all_tables()) {
    GpuTables tables(test::test_table_cache());
    tables.require(std::vector<std::string>{t.source.id});
    const GLuint texture = tables.texture(t.source.id);
    ASSERT_NE(texture, 0u) << t.source.id;
    // The internal formats tables use: RGB16F (6 bytes a texel), RGBA32F (16; the LTC tables).
    GLint format = 0, levels = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    ASSERT_TRUE(format == GL_RGB16F || format == GL_RGBA32F) << t.source.id << ": internal format " << format;
    const std::size_t texel_bytes = format == GL_RGB16F ? 6 : 16;
    std::size_t base = 0, with_mips = 0;
    for (GLint level = 0; level < levels; ++level) {
      GLint w = 0, h = 0, d = 0;
      glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
      glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
      glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_DEPTH, &d);
      const std::size_t bytes = static_cast<std::size_t>(w) * h * d * texel_bytes;
      if (level == 0) base = bytes;
      with_mips += bytes;
    }
    EXPECT_EQ(base, t.gpu_bytes.base) << t.source.id;
    EXPECT_EQ(with_mips, t.gpu_bytes.with_mips) << t.source.id;
  }
  // The paper's dictionary: 64 texels x 1024 layers x 6 bytes, and its 1D chain of 7 levels.
  EXPECT_EQ(find_table("glint-dictionary").gpu_bytes.base, 393216u);
  EXPECT_EQ(find_table("glint-dictionary").gpu_bytes.with_mips, 780288u);
  // The LTC tables: 64 x 64 texels x 2 layers x 16 bytes, no mips.
  for (const char* id : {"ltc-ggx", "ltc-ndf"}) {
    EXPECT_EQ(find_table(id).gpu_bytes.base, 131072u) << id;
    EXPECT_EQ(find_table(id).gpu_bytes.with_mips, 131072u) << id;
  }
}

TEST(Tables, ARequiredTableIsMadeResidentOnce) {
  context();
  GpuTables tables(test::test_table_cache());
  EXPECT_EQ(tables.texture("glint-dictionary"), 0u);
  const std::vector<std::string> ids{"glint-dictionary", "glint-dictionary"};
  tables.require(ids);
  tables.require(ids);
  ASSERT_EQ(tables.reports().size(), 1u);
  EXPECT_NE(tables.texture("glint-dictionary"), 0u);
  EXPECT_THROW(tables.require(std::vector<std::string>{"no-such-table"}), InputError);
}

/// A sphere of a glinty material, and the same with a plain one.
test::TestScene glinty_scene() { return test::TestScene().film(16, 12).glinty_material("g").sphere("g").point_light({0, 2, 3}); }
test::TestScene plain_scene() { return test::TestScene().film(16, 12).material("m").sphere("m").point_light({0, 2, 3}); }

TEST(Tables, AGlintySceneHasTheDictionaryForEveryMethodAndTheReference) {
  SceneFixture glinty(glinty_scene());
  EXPECT_NE(glinty.gpu->resources().tables().texture("glint-dictionary"), 0u) << "glinty materials read it in any method";
  EXPECT_EQ(glinty.gpu->scene_resource_ids(), std::vector<std::string>{"table:glint-dictionary"})
      << "what the reference reads, in its cache key";
  SceneFixture plain(plain_scene());
  EXPECT_EQ(plain.gpu->resources().tables().texture("glint-dictionary"), 0u) << "nothing reads it: not built";
  EXPECT_TRUE(plain.gpu->scene_resource_ids().empty());
}

TEST(Tables, AMethodsDeclaredTablesAreResidentWhenItDraws) {
  SceneFixture plain(plain_scene());
  (void)plain.method("conventional");
  EXPECT_EQ(plain.gpu->resources().tables().texture("glint-dictionary"), 0u);
  (void)plain.method("chermain2020");
  EXPECT_NE(plain.gpu->resources().tables().texture("glint-dictionary"), 0u);
}

}  // namespace
}  // namespace glintlab
