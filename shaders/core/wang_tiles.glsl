// Wang tiles' placement on the GPU, the twin of src/scene/normal_maps/wang_tiles.hpp (tested equal:
// WangTilesGlsl.*): the plane's lattice of tile corners hashed (mod `period` where it is above 0,
// so that the tiling repeats every period cells), each corner's two bits the colours of the edges
// leaving it along +u and +v; a cell's tile is north + 2 east + 4 south + 8 west, and the 16 tiles
// lie in an atlas of 4 x 4 tiles (tile t at column t mod 4, row t / 4).
#ifndef WANG_TILES_GLSL
#define WANG_TILES_GLSL

#include "core/sampling.glsl"  // hash3
#include "core/wrap.glsl"      // floorMod

// Bit 0: the colour of corner c's edge along u; bit 1: of its edge along v.
uint wangCornerBits(ivec2 c, int period, uint seed) {
  if (period > 0) c = floorMod(c, ivec2(period));
  return hash3(uvec3(uvec2(c), seed)) >> 30;
}

int wangTile(ivec2 cell, int period, uint seed) {
  uint here = wangCornerBits(cell, period, seed);
  uint north = wangCornerBits(cell + ivec2(0, 1), period, seed) & 1u;
  uint east = wangCornerBits(cell + ivec2(1, 0), period, seed) >> 1;
  return int(north + 2u * east + 4u * (here & 1u) + 8u * (here >> 1));
}

// The atlas texel holding texel t of the tiled surface (|t| below 2^23: exact in float).
ivec2 wangAtlasTexel(ivec2 t, int tileSize, int period, uint seed) {
  ivec2 cell = ivec2(floor((vec2(t) + 0.5) / float(tileSize)));
  int tile = wangTile(cell, period, seed);
  return ivec2(tile & 3, tile >> 2) * tileSize + (t - cell * tileSize);
}

#endif
