// Wang tiles' placement in GLSL (shaders/core/wang_tiles.glsl) against the C++ tile set and lattice
// (src/scene/normal_maps/wang_tiles.hpp): at texels of the surface near the origin and far from it,
// of either sign, unbounded or repeating, the atlas texel the shader reads holds the surface's texel.
#include <gtest/gtest.h>

#include <random>

#include "gl_fixture.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

using namespace glintlab;
using namespace glintlab::test;

TEST(WangTilesGlsl, TheShaderReadsTheSurfacesTexelFromTheAtlas) {
  const WangTileSet set(generate_bumps(64, 0.3f, 24, 8, 1), 24, 2);
  const NormalMap atlas = set.atlas();
  std::mt19937 rng(5);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 2000; ++i) {
    const int range = i < 1000 ? 200 : 4000000;  // near the origin, then far from it
    std::uniform_int_distribution<int> coordinate(-range, range);
    const std::uint32_t seed = i % 3 == 0 ? 0u : 1000u + static_cast<std::uint32_t>(i % 7);
    const int period = i % 2 == 0 ? 0 : 1 + i % 13;  // unbounded, or repeating every 1 .. 13 tiles
    a.emplace_back(static_cast<float>(coordinate(rng)), static_cast<float>(coordinate(rng)), 24.0f, static_cast<float>(seed));
    b.emplace_back(static_cast<float>(period), 0.0f, 0.0f, 0.0f);
  }
  const auto out = evaluate_glsl("#include \"core/wang_tiles.glsl\"\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  ivec2 t = ivec2(a.xy);
  ivec2 at = wangAtlasTexel(t, int(a.z), int(b.x), uint(a.w));
  int tileSize = int(a.z);
  ivec2 cell = ivec2(floor((vec2(t) + 0.5) / float(tileSize)));
  return vec4(at, float(wangTile(cell, int(b.x), uint(a.w))), 0.0);
})", a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto x = static_cast<std::int64_t>(a[i].x), y = static_cast<std::int64_t>(a[i].y);
    const WangLattice lattice(static_cast<std::uint32_t>(a[i].w), static_cast<std::int32_t>(b[i].x));
    const std::int64_t cx = (x >= 0 ? x : x - 23) / 24, cy = (y >= 0 ? y : y - 23) / 24;
    ASSERT_EQ(static_cast<int>(out[i].z), lattice.cell(static_cast<std::int32_t>(cx), static_cast<std::int32_t>(cy)).tile())
        << "texel " << x << ", " << y;
    const int ax = static_cast<int>(out[i].x), ay = static_cast<int>(out[i].y);
    ASSERT_TRUE(ax >= 0 && ay >= 0 && ax < atlas.width && ay < atlas.height) << ax << ", " << ay;
    ASSERT_EQ(atlas.normals[static_cast<std::size_t>(ay) * atlas.width + ax], set.surface_texel(lattice, x, y))
        << "texel " << x << ", " << y;
  }
}
