#pragma once
// Wang tiles of a normal map (Deng et al. 2022 sec. 5.5: a surface of any size at the storage of a
// few tiles). Two colours per edge direction, so 16 tiles cover every colouring of a cell's four
// edges (Cohen et al. 2003). Where each tile goes is not stored: the plane's lattice of tile
// corners is hashed, and each corner sets the colours of the two edges that leave it (towards +u
// and towards +v; the paper's "right and bottom" edges, its image rows running down), a variant of
// Lagae & Dutre 2005's corner hashing that needs two random bits a corner, drawn by the shaders'
// own hash (core/shader_hash.hpp). Any cell's tile is then three hashes away, at any position.
//
// Each tile is cut from the input map as Cohen et al. do: one diamond (a square turned 45 degrees)
// per edge colour, taken from the input at its own offset, centred on the edge; a tile is the four
// triangles between its diagonals, each from the diamond of its edge's colour. Two tiles that share
// an edge take the two halves of the same diamond, so across every edge the texels on either side
// are neighbours in the input: no seam between tiles. Inside a tile two diamonds meet along each
// half-diagonal; as Cohen et al. (after Efros & Freeman 2001's quilting) the boundary there is the
// minimum-error cut, the path near the diagonal along which the two diamonds differ least.
//
// With two colours a direction there are only four diamonds, and a surface made of them alone is a
// lattice of edge-centred diamonds of two contents each: a pattern at the tile's period that the eye
// finds at once, whatever the input. So past a band of T / 8 texels from its edges each tile takes a
// patch of its own from the input (16 more samples), the boundary again a minimum-error cut (per
// position along an edge, the depth at which the diamond gives way); the edges, and so the absence
// of seams between tiles, are the diamonds'.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// A cell's edge colours (0 or 1): north and south are its edges along u (at v = j + 1 and j),
/// east and west those along v (at u = i + 1 and i).
struct WangEdges {
  int north = 0, east = 0, south = 0, west = 0;
  /// The tile of this colouring: north + 2 east + 4 south + 8 west.
  [[nodiscard]] int tile() const { return north + 2 * east + 4 * south + 8 * west; }
  bool operator==(const WangEdges&) const = default;
};

/// The lattice of tile corners, hashed with `seed`: corner (i, j) colours the edge from it to
/// (i + 1, j) and the edge from it to (i, j + 1). With a `period` P > 0 corners are taken mod P, so
/// that the tiling repeats every P cells (a map's repeat over uv); 0: unbounded.
class WangLattice {
 public:
  explicit WangLattice(std::uint32_t seed, std::int32_t period = 0) : seed_(seed), period_(period) {}
  /// The colour of the edge along u that starts at corner (i, j).
  [[nodiscard]] int edge_along_u(std::int32_t i, std::int32_t j) const;
  /// The colour of the edge along v that starts at corner (i, j).
  [[nodiscard]] int edge_along_v(std::int32_t i, std::int32_t j) const;
  /// Cell (i, j), the square from corner (i, j) to (i + 1, j + 1).
  [[nodiscard]] WangEdges cell(std::int32_t i, std::int32_t j) const;

 private:
  /// Two independent bits of corner (i, j): bit 0 its edge along u, bit 1 its edge along v.
  [[nodiscard]] std::uint32_t corner_bits(std::int32_t i, std::int32_t j) const;
  std::uint32_t seed_;
  std::int32_t period_;
};

/// The 16 tiles of a normal map, each tile_size texels square, and where every texel came from.
class WangTileSet {
 public:
  /// Cuts the tiles from `input` (read periodically: glintlab's generated maps tile), the four
  /// diamonds and the 16 centre patches at offsets drawn from `seed`. tile_size at least 2 and at
  /// most the input's size. `cut` false: straight boundaries (the diagonals, the band's edge: to
  /// measure what the cuts save).
  WangTileSet(const NormalMap& input, int tile_size, std::uint32_t seed, bool cut = true);

  [[nodiscard]] int tile_size() const { return tile_size_; }
  /// Texel (x, y) of tile t (0 .. 15), x and y in [0, tile_size).
  [[nodiscard]] const glm::vec3& texel(int t, int x, int y) const;
  /// The input texel it was copied from.
  [[nodiscard]] std::array<int, 2> source(int t, int x, int y) const;
  /// Texel (x, y) of the unbounded tiled surface, any integers: cell (x / T, y / T) of `lattice`
  /// (rounded down), its tile's texel (x mod T, y mod T).
  [[nodiscard]] const glm::vec3& surface_texel(const WangLattice& lattice, std::int64_t x, std::int64_t y) const;
  /// The 16 tiles as one map of 4 x 4 tiles, tile t at column t mod 4 and row t / 4 (what the GPU
  /// reads: shaders/glints/normal-map/wang_tiles.glsl).
  [[nodiscard]] NormalMap atlas() const;
  /// Bytes the tiles hold: constant in the size of the surface they cover.
  [[nodiscard]] std::size_t bytes() const { return normals_.size() * sizeof(glm::vec3); }

 private:
  int tile_size_;
  std::vector<glm::vec3> normals_;                ///< 16 tiles, row after row
  std::vector<std::array<int, 2>> sources_;
};

/// The Wang-tiled surface of `tiling` made from `input`: its 16 tiles' atlas, with `wang` set.
/// Throws InputError (naming the key) for a tile size the input cannot hold.
NormalMap make_wang_tiled_map(const NormalMap& input, const WangTiling& tiling);

/// Texel (x, y) of a map's surface, any integers (wrapped by its surface size): a plain map's own,
/// or, with Wang tiles, the atlas texel of the tile that its lattice puts there.
[[nodiscard]] const glm::vec3& surface_texel(const NormalMap& map, std::int64_t x, std::int64_t y);

/// The width x height texels of a map's surface from (x0, y0) (surface_texel's), as a plain map.
[[nodiscard]] NormalMap surface_window(const NormalMap& map, std::int64_t x0, std::int64_t y0, int width, int height);

/// Where texel (x, y) of a Wang-tiled map's surface lies in its atlas (x, y wrapped by the surface size).
[[nodiscard]] std::array<int, 2> wang_atlas_texel(const WangTiling& tiling, std::int64_t x, std::int64_t y);

}  // namespace glintlab
