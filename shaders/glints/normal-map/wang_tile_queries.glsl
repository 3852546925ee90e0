// Deng et al. 2022's queries on a surface of Wang tiles (sec. 5.5, fig. 12), the GLSL twin of
// src/prefilter/wang_tile_pyramids.cpp (wang_tiles_density): a footprint's NDF is the sum over the
// cells it reaches of the cell's tile's partial NDF at the footprint's centre relative to the cell,
// each from that tile's pyramid (prefiltered_ndf.glsl; a material's 16 tile headers in
// src/prefilter/prefiltered_ndf_layout.hpp). The tile at a cell comes from the hashed lattice
// (core/wang_tiles.glsl), as the surface's texels do (core/normal_map.glsl).
//
// The cost is one pyramid query per cell reached: 1 to 4 while a footprint's reach (about 3 sigma)
// is under a tile, up to 8 x 8 at the last level's sigma (about the tile's size), growing with its
// area past that. Past WANG_MAX_CELLS cells a stratified subset stands for them: the cells cut into
// s x s blocks, one cell per block chosen by a hash of the block (fixed on the surface), weighed
// s^2; unbiased over the hash, its error the tiles' arrangement's, not a lost part of the footprint.
#include "core/wang_tiles.glsl"
#include "glints/normal-map/ndf_sampling.glsl"  // pndfMass, pndfSample, the reservoir
#include "glints/normal-map/prefiltered_ndf.glsl"

const int WANG_MAX_CELLS = 64;

struct WangPyramids {
  uint table;  // the word of the material's 16 tile header offsets
  int tileSize, tiles;
  uint seed;
  int elementsPerTexel;
  float firstSigma;
};

WangPyramids wangPyramids(int material, int tileSize, int tiles, uint seed) {
  WangPyramids w;
  w.table = pndfRecords[material];
  w.tileSize = tileSize;
  w.tiles = tiles;
  w.seed = seed;
  const PndfHeader first = pndfHeaderAt(pndfRecords[w.table]);
  w.elementsPerTexel = first.elementsPerTexel;
  w.firstSigma = pndfFirstSigma(first);
  return w;
}

PndfHeader wangTileHeader(WangPyramids w, int tile) { return pndfHeaderAt(pndfRecords[w.table + uint(tile)]); }

// The cells a footprint reaches (wang_footprint_reach), as a block-strided walk: `count` cells of
// stride `stride` from `first`, each standing for stride^2.
struct WangCells {
  ivec2 first, count;
  int stride;
};

WangCells wangCells(WangPyramids w, vec2 centre, float sigma) {
  const float element = pndfElementSigma(w.elementsPerTexel);
  const float reach = 3.0 * sqrt(sigma * sigma + element * element) + 1.0;
  const ivec2 lo = ivec2(floor((centre - reach) / float(w.tileSize))), hi = ivec2(floor((centre + reach) / float(w.tileSize)));
  WangCells c;
  c.stride = 1;
  const ivec2 n = hi - lo + 1;
  while ((n.x + c.stride - 1) / c.stride * ((n.y + c.stride - 1) / c.stride) > WANG_MAX_CELLS) ++c.stride;
  c.first = lo;
  c.count = (n + c.stride - 1) / c.stride;
  return c;
}

// Cell i of the walk (the block's own at stride 1, else the one its hash picks), and its tile.
ivec2 wangCell(WangPyramids w, WangCells c, int i, out int tile) {
  ivec2 block = ivec2(i % c.count.x, i / c.count.x);
  ivec2 cell = c.first + block * c.stride;
  if (c.stride > 1) {
    const uint h = hash3(uvec3(uvec2(c.first + block * c.stride), uint(c.stride) ^ 0x5eedu));
    cell += ivec2(int(h % uint(c.stride)), int((h / uint(c.stride)) % uint(c.stride)));
  }
  tile = wangTile(cell, w.tiles, w.seed);
  return cell;
}

int wangCellCount(WangCells c) { return c.count.x * c.count.y; }
// Each cell stands for stride^2 of them.
float wangCellWeight(WangCells c) { return float(c.stride * c.stride); }

// Cell i's tile's pyramid, and the footprint's centre relative to the cell.
PndfHeader wangCellPyramid(WangPyramids w, WangCells c, int i, vec2 centre, out vec2 local) {
  int tile;
  const ivec2 cell = wangCell(w, c, i, tile);
  local = centre - vec2(cell * w.tileSize);
  return wangTileHeader(w, tile);
}

float wangDensity(WangPyramids w, vec2 centre, float sigma, vec2 s) {
  const WangCells c = wangCells(w, centre, sigma);
  float sum = 0.0;
  for (int i = 0; i < wangCellCount(c); ++i) {
    vec2 local;
    sum += pndfDensity(wangCellPyramid(w, c, i, centre, local), local, sigma, s);
  }
  return wangCellWeight(c) * sum;
}

float wangRangeMean(WangPyramids w, vec2 centre, float sigma, vec2 lo, vec2 hi, bool prefixTables) {
  const WangCells c = wangCells(w, centre, sigma);
  float sum = 0.0;
  for (int i = 0; i < wangCellCount(c); ++i) {
    vec2 local;
    sum += pndfRangeMean(wangCellPyramid(w, c, i, centre, local), local, sigma, lo, hi, prefixTables);
  }
  return wangCellWeight(c) * sum;
}

// The footprint's mass in the square (the sampler's normaliser).
float wangMass(WangPyramids w, vec2 centre, float sigma) {
  const WangCells c = wangCells(w, centre, sigma);
  float sum = 0.0;
  for (int i = 0; i < wangCellCount(c); ++i) {
    vec2 local;
    sum += pndfMass(wangCellPyramid(w, c, i, centre, local), local, sigma);
  }
  return wangCellWeight(c) * sum;
}

// Sampling across tiles: a cell by its mass (a weighted reservoir; the paper picks one uniformly),
// then its tile's sampler (pndfSample) at the centre relative to the cell. The density of s is
// then the sum over cells of mass_i / total times cell i's density over its mass: wangDensity over
// wangMass, which the pdf returned is.
NdfSample wangSample(WangPyramids w, vec2 centre, float sigma, uint seed, vec2 u) {
  const WangCells c = wangCells(w, centre, sigma);
  float total = 0.0;
  int chosen = -1;
  for (int i = 0; i < wangCellCount(c); ++i) {
    vec2 local;
    const float m = pndfMass(wangCellPyramid(w, c, i, centre, local), local, sigma);
    if (ndfReservoirTakes(m, total, ndfChoiceUniform(seed, 30u, uint(i)))) chosen = i;
  }
  if (chosen < 0) return NO_NDF_SAMPLE;
  vec2 local;
  const PndfHeader h = wangCellPyramid(w, c, chosen, centre, local);
  NdfSample x = pndfSample(h, local, sigma, seed, u);
  if (x.pdf <= 0.0) return NO_NDF_SAMPLE;
  x.pdf = wangDensity(w, centre, sigma, x.s) / (wangCellWeight(c) * total);
  return x.pdf > 0.0 ? x : NO_NDF_SAMPLE;
}
