// Wang tiles (scene/normal_maps/wang_tiles.hpp): the hashed lattice is deterministic, neighbours
// share their edge's colour, and the colours are uniform and independent (chi-square over the
// corners' bits and over the cells' 16 tiles); the tiles are cut so that across every edge the
// texels on either side are neighbours in the input (no seam between tiles), each texel is the
// input's at its source, and the storage is the 16 tiles whatever the surface's size.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <set>

#include "chi_square.hpp"
#include "core/error.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

using namespace glintlab;
using glintlab::test::ChiSquare;
using glintlab::test::chi_square;

namespace {

/// a and b are neighbours of a periodic n x n input, b one texel from a along axis `axis`.
bool one_step(std::array<int, 2> a, std::array<int, 2> b, int axis, int n) {
  const int other = 1 - axis;
  return b[other] == a[other] && (a[axis] + 1) % n == b[axis];
}

}  // namespace

TEST(WangTiles, NeighbouringCellsShareTheirEdgesColour) {
  const WangLattice lattice(7);
  for (int j = -20; j < 20; ++j)
    for (int i = -20; i < 20; ++i) {
      const WangEdges c = lattice.cell(i, j);
      EXPECT_EQ(c.east, lattice.cell(i + 1, j).west) << i << ", " << j;
      EXPECT_EQ(c.north, lattice.cell(i, j + 1).south) << i << ", " << j;
      EXPECT_EQ(c, WangLattice(7).cell(i, j)) << "deterministic";
    }
  // Another seed, another arrangement.
  int differ = 0;
  for (int i = 0; i < 64; ++i) differ += lattice.cell(i, 3).tile() != WangLattice(8).cell(i, 3).tile();
  EXPECT_GT(differ, 32);
}

TEST(WangTiles, ColoursAreUniformAndIndependent) {
  const WangLattice lattice(1234);
  const int n = 256;
  std::vector<double> corners(4, 0.0), tiles(16, 0.0);
  for (int j = -n / 2; j < n / 2; ++j)
    for (int i = -n / 2; i < n / 2; ++i) {
      corners[lattice.edge_along_u(i, j) + 2 * lattice.edge_along_v(i, j)] += 1;
      tiles[lattice.cell(i, j).tile()] += 1;
    }
  const ChiSquare by_corner = chi_square(corners, std::vector<double>(4, n * n / 4.0));
  const ChiSquare by_tile = chi_square(tiles, std::vector<double>(16, n * n / 16.0));
  std::cout << "corners' bits " << by_corner << "; cells' tiles " << by_tile << "\n";
  EXPECT_TRUE(by_corner.passes(2)) << by_corner;
  EXPECT_TRUE(by_tile.passes(2)) << by_tile;
}

TEST(WangTiles, NoSeamAcrossATileEdgeAndEveryTexelIsTheInputs) {
  const NormalMap input = generate_bumps(64, 0.3f, 32, 8, 5);
  for (const int t : {16, 17}) {  // even and odd tiles
    const WangTileSet set(input, t, 99);
    EXPECT_EQ(set.bytes(), 16u * t * t * sizeof(glm::vec3));
    for (int tile = 0; tile < 16; ++tile)
      for (int y = 0; y < t; ++y)
        for (int x = 0; x < t; ++x) {
          const auto s = set.source(tile, x, y);
          ASSERT_EQ(set.texel(tile, x, y), input.normals[static_cast<std::size_t>(s[1]) * 64 + s[0]]);
        }
    // Every pair of tiles that may meet across an edge (the left one's east colour is the right
    // one's west): the texels facing each other away from the corners are input neighbours.
    int pairs = 0;
    for (int a = 0; a < 16; ++a)
      for (int b = 0; b < 16; ++b) {
        const int a_east = (a >> 1) & 1, b_west = (b >> 3) & 1, a_north = a & 1, b_south = (b >> 2) & 1;
        for (int k = 1; k < t - 1; ++k) {
          if (a_east == b_west) {
            EXPECT_TRUE(one_step(set.source(a, t - 1, k), set.source(b, 0, k), 0, 64)) << a << " | " << b << ", row " << k;
            ++pairs;
          }
          if (a_north == b_south) {
            EXPECT_TRUE(one_step(set.source(a, k, t - 1), set.source(b, k, 0), 1, 64)) << a << " / " << b << ", column " << k;
            ++pairs;
          }
        }
      }
    EXPECT_GT(pairs, 0);
  }
}

TEST(WangTiles, TheSurfaceAnywhereIsItsCellsTile) {
  const NormalMap input = generate_flakes(64, 8, 0.3f, 2);
  const WangTileSet set(input, 16, 3);
  const WangLattice lattice(11);
  std::set<int> seen;
  for (std::int64_t y : {-1000001LL, -17LL, -1LL, 0LL, 15LL, 16LL, 123456789LL})
    for (std::int64_t x : {-33LL, -16LL, 0LL, 31LL, 987654321LL}) {
      const std::int64_t i = static_cast<std::int64_t>(std::floor(x / 16.0)), j = static_cast<std::int64_t>(std::floor(y / 16.0));
      const int tile = lattice.cell(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)).tile();
      seen.insert(tile);
      EXPECT_EQ(set.surface_texel(lattice, x, y), set.texel(tile, static_cast<int>(x - 16 * i), static_cast<int>(y - 16 * j)))
          << x << ", " << y;
    }
  EXPECT_GT(seen.size(), 4u);
  EXPECT_THROW(WangTileSet(input, 1, 0), std::invalid_argument);
  EXPECT_THROW(WangTileSet(input, 65, 0), std::invalid_argument);
}

// Each tile's interior is a patch of its own: the diamonds, shared by every tile of an edge's colour,
// keep a band along the edges, and past it no two tiles take their texels from the same place, so
// the surface is not a lattice of four diamonds' contents.
TEST(WangTiles, EachTileHasAnInteriorOfItsOwn) {
  const NormalMap input = generate_bumps(128, 0.3f, 32, 8, 5);
  const int t = 32;
  const WangTileSet set(input, t, 7);
  for (int a = 0; a < 16; ++a) {
    const auto centre = set.source(a, t / 2, t / 2);
    for (int b = a + 1; b < 16; ++b) EXPECT_NE(set.source(b, t / 2, t / 2), centre) << a << ", " << b;
    // The band: every texel within one texel of an edge comes from the edge's diamond, which the
    // tiles that share the colour share (the south edge's row of tile a and of another tile of its colour).
    for (int b = 0; b < 16; ++b)
      if (b != a && ((b >> 2) & 1) == ((a >> 2) & 1))
        for (int x = 1; x < t - 1; ++x) EXPECT_EQ(set.source(b, x, 0), set.source(a, x, 0)) << a << ", " << b << ", x " << x;
  }
}

// A map of Wang tiles (make_wang_tiled_map): the atlas of the set's tiles, a surface of P T texels
// that repeats every P tiles (the lattice's period), each texel its cell's tile's; the storage is
// the 16 tiles whatever P is.
TEST(WangTiles, ATiledMapsSurfaceRepeatsWithItsPeriodAndReadsTheAtlas) {
  const NormalMap input = generate_bumps(48, 0.3f, 24, 6, 4);
  const WangTiling tiling{.tile_size = 12, .tiles = 5, .seed = 9};
  const NormalMap map = make_wang_tiled_map(input, tiling);
  ASSERT_TRUE(map.wang.has_value());
  EXPECT_EQ(map.width, 48);
  EXPECT_EQ(map.surface_width(), 60);
  EXPECT_EQ(make_wang_tiled_map(input, {.tile_size = 12, .tiles = 500, .seed = 9}).normals.size(), map.normals.size());
  const WangTileSet set(input, 12, 9);
  const WangLattice lattice(9, 5);
  for (std::int64_t y = -13; y < 75; y += 7)
    for (std::int64_t x = -30; x < 130; x += 3) {
      EXPECT_EQ(surface_texel(map, x, y), set.surface_texel(lattice, x, y)) << x << ", " << y;
      EXPECT_EQ(surface_texel(map, x + 60, y - 120), surface_texel(map, x, y)) << x << ", " << y;
    }
  // Unbounded, the lattice does not repeat: some cell P away has another tile.
  const WangLattice unbounded(9);
  bool differs = false;
  for (int i = 0; i < 20; ++i) differs |= unbounded.cell(i, 0).tile() != unbounded.cell(i + 5, 0).tile();
  EXPECT_TRUE(differs);
  EXPECT_THROW(make_wang_tiled_map(input, {.tile_size = 49, .tiles = 2, .seed = 0}), InputError);
  EXPECT_THROW(make_wang_tiled_map(input, {.tile_size = 8, .tiles = 0, .seed = 0}), InputError);
}

// The seams inside the tiles: neighbouring texels that are not neighbours in the input, and how
// much their normals differ. The minimum-error cuts (between diamonds near the diagonals, between
// the edges' diamonds and the tile's centre patch) lower it against straight boundaries (measured
// 0.88 and 0.87 of it on a rough bumps map: the centre patch's boundary, about 4 T texels long
// between uncorrelated samples, leaves the cuts less to choose from than the diagonals alone, 0.45).
TEST(WangTiles, TheMinimumErrorCutLowersTheSeamsInsideTiles) {
  const NormalMap input = generate_bumps(128, 0.4f, 48, 12, 8);
  auto seam_energy = [&](const WangTileSet& set) {
    const int t = set.tile_size();
    double energy = 0;
    for (int tile = 0; tile < 16; ++tile)
      for (int y = 0; y < t; ++y)
        for (int x = 0; x < t; ++x)
          for (int axis = 0; axis < 2; ++axis) {
            const int nx = x + (axis == 0), ny = y + (axis == 1);
            if (nx >= t || ny >= t) continue;
            if (one_step(set.source(tile, x, y), set.source(tile, nx, ny), axis, 128)) continue;
            const glm::vec3 d = set.texel(tile, x, y) - set.texel(tile, nx, ny);
            energy += glm::dot(d, d);
          }
    return energy;
  };
  for (const int t : {32, 33}) {
    const double straight = seam_energy(WangTileSet(input, t, 4, false)), cut = seam_energy(WangTileSet(input, t, 4));
    std::cout << "tile " << t << ": seam energy straight " << straight << ", cut " << cut << "\n";
    EXPECT_LT(cut, 0.9 * straight) << t;
  }
}
