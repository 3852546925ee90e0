// `glintlab program` (src/eval/program_command.hpp): the text of a forward program in the material
// variant the options choose, Wang tiles included, and the options it refuses.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "eval/program_command.hpp"

using namespace glintlab;

TEST(ProgramCommand, AWangTiledMapsVariantReadsItsTilesPyramids) {
  ProgramOptions o;
  o.method = "deng2022";
  o.material_kind = "normal-map-glints";
  o.normal_map = true;
  const std::string plain = program_source(o);
  o.wang_tiles = true;
  const std::string tiled = program_source(o);
  EXPECT_NE(plain.find("#define MATERIAL_WANG_TILES 0"), std::string::npos);
  EXPECT_NE(tiled.find("#define MATERIAL_WANG_TILES 1"), std::string::npos);
  EXPECT_NE(tiled.find("wangPyramids(uMaterial"), std::string::npos);
  // Wang tiles belong to normal-map-glints materials' maps only.
  o.material_kind = "microfacet";
  EXPECT_THROW((void)program_source(o), InputError);
  o.material_kind = "normal-map-glints";
  o.normal_map = false;
  EXPECT_THROW((void)program_source(o), InputError);
}
