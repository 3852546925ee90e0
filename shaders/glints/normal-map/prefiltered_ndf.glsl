// Deng et al. 2022's queries on a material's CP-compressed NDF pyramid (docs/methods.md#deng2022):
// the GLSL twin of src/prefilter/prefiltered_ndf.cpp, reading the layout of
// src/prefilter/prefiltered_ndf_layout.hpp from two storage buffers. The queries take the
// material's header, read once per pixel (pndfHeader), not once per light. Nothing here feeds a
// derivative, so llvmpipe's masked helper-invocation loads do not matter.
#include "generated/gpu_contract.glsl"
#include "core/wrap.glsl"

layout(std430, binding = PREFILTERED_NDF_RECORDS_BINDING) readonly buffer PrefilteredNdfRecords { uint pndfRecords[]; };
layout(std430, binding = PREFILTERED_NDF_VALUES_BINDING) readonly buffer PrefilteredNdfValues { float pndfValues[]; };
// The same floats as vec4s: the factors' rank-R rows are runs of aligned vec4s where R is a
// multiple of 4 (src/prefilter/prefiltered_ndf_layout.hpp aligns every region).
layout(std430, binding = PREFILTERED_NDF_VALUES_BINDING) readonly buffer PrefilteredNdfVectors { vec4 pndfVectors[]; };

const uint PNDF_NONE = 0xffffffffu;

// The pyramid's N, B and R as constants where the including method compiles them in (its
// parameters fix them; 0: read from the header, as here by default). A constant folds through
// every query once the header is inlined: loops over R unroll, divisions by N and B become shifts
// where they are powers of two.
#ifndef PNDF_COMPILED_SHAPE
const int PNDF_FIXED_N = 0, PNDF_FIXED_B = 0, PNDF_FIXED_RANK = 0;
#endif
// A rank compiled in as a multiple of 4: the loops over it read 4 ranks per vec4 load.
const bool PNDF_VECTOR_LOADS = PNDF_FIXED_RANK > 0 && PNDF_FIXED_RANK % 4 == 0;

// Ranks r .. r + 3 of the row at float `at` (a multiple of 4 where PNDF_VECTOR_LOADS holds).
vec4 pndfRow4(uint at, int r) { return pndfVectors[(at >> 2u) + uint(r >> 2)]; }
// Four consecutive floats from any float index (the box prefix tables' rows are not aligned).
vec4 pndfFloats4(uint at) { return vec4(pndfValues[at], pndfValues[at + 1u], pndfValues[at + 2u], pndfValues[at + 3u]); }

struct PndfHeader {
  uint at;  // the header's word
  int levels, n, b, rank;
  float extent;
  uint footprints, groups, angular, rows;
  uint tables;  // the box prefix tables' first float, or PNDF_NONE
  bool partial;  // a Wang tile's pyramid (src/prefilter/prefiltered_ndf.hpp, PrefilteredNdf::partial)
  vec2 size;     // its map's (tile's) texels
  int elementsPerTexel;
  float topShare;  // a tile's: the share of its last level's footprint at its centre on it
};

// The pyramid whose header starts at word `at`.
PndfHeader pndfHeaderAt(uint at) {
  PndfHeader h;
  h.at = at;
  h.levels = int(pndfRecords[h.at + 0u]);
  h.n = PNDF_FIXED_N > 0 ? PNDF_FIXED_N : int(pndfRecords[h.at + 1u]);
  h.b = PNDF_FIXED_B > 0 ? PNDF_FIXED_B : int(pndfRecords[h.at + 2u]);
  h.rank = PNDF_FIXED_RANK > 0 ? PNDF_FIXED_RANK : int(pndfRecords[h.at + 3u]);
  h.extent = uintBitsToFloat(pndfRecords[h.at + 4u]);
  h.footprints = pndfRecords[h.at + 5u];
  h.groups = pndfRecords[h.at + 6u];
  h.angular = pndfRecords[h.at + 7u];
  h.rows = pndfRecords[h.at + 8u];
  h.tables = pndfRecords[h.at + 11u];
  h.size = vec2(pndfRecords[h.at + 9u], pndfRecords[h.at + 10u]);
  h.partial = pndfRecords[h.at + 12u] != 0u;
  h.elementsPerTexel = int(pndfRecords[h.at + 13u]);
  h.topShare = uintBitsToFloat(pndfRecords[h.at + 14u]);
  return h;
}

// A material's pyramid (of a plain map).
PndfHeader pndfHeader(int material) { return pndfHeaderAt(pndfRecords[material]); }

bool pndfPresent(int material) { return material >= 0 && pndfRecords[material] != PNDF_NONE; }

uint pndfLevelWord(PndfHeader h, int level, uint field) { return pndfRecords[h.at + 16u + 8u * uint(level) + field]; }

// The footprint sigma (texels) of the pyramid's first level.
float pndfFirstSigma(PndfHeader h) { return uintBitsToFloat(pndfLevelWord(h, 0, 5u)); }

// Whether block `bit` of footprint f is kept, and the float index of its row of the long factor.
bool pndfBlockRow(PndfHeader h, uint f, int bit, out uint row) {
  const uint at = h.footprints + 4u * f;
  const uint lo = pndfRecords[at], hi = pndfRecords[at + 1u];
  const bool kept = ((bit < 32 ? lo >> uint(bit) : hi >> uint(bit - 32)) & 1u) != 0u;
  const uint below = bit >= 32 ? uint(bitCount(lo)) + uint(bitCount(hi & ((1u << uint(bit - 32)) - 1u)))
                               : uint(bitCount(lo & ((1u << uint(bit)) - 1u)));
  row = h.rows + (pndfRecords[at + 2u] + below) * uint(h.rank);
  return kept;
}

// 1 where block `bit` of footprint f is kept, with its row; 0 where it was dropped, with the first
// row, so that branch-free sums read a valid row and weigh it 0.
float pndfKeptRow(PndfHeader h, uint f, int bit, out uint row) {
  const bool kept = pndfBlockRow(h, f, bit, row);
  row = kept ? row : h.rows;
  return kept ? 1.0 : 0.0;
}

uint pndfGroupAngular(PndfHeader h, uint f) { return h.angular + pndfRecords[h.groups + pndfRecords[h.footprints + 4u * f + 3u]]; }

// S(t) = S[floor t] + frac(t) m[floor t]: a factor column's integral from 0 to t (t in [0, B]).
float pndfPrefix(PndfHeader h, uint sums, uint factor, float t, int r) {
  const int f = min(int(t), h.b - 1);
  return pndfValues[sums + uint(f * h.rank + r)] + (t - float(f)) * pndfValues[factor + uint(f * h.rank + r)];
}

// pndfPrefix for ranks r .. r + 3 (PNDF_VECTOR_LOADS: sums and factor are aligned rows).
vec4 pndfPrefix4(PndfHeader h, uint sums, uint factor, float t, int r) {
  const int f = min(int(t), h.b - 1);
  return pndfRow4(sums + uint(f * h.rank), r) + (t - float(f)) * pndfRow4(factor + uint(f * h.rank), r);
}

// The integral of footprint f's pixels over [x0, x1] (continuous pixel coordinates inside the
// image), block by block through the prefix sums (eq. 7).
float pndfPixelRangeSum(PndfHeader h, uint f, vec2 x0, vec2 x1) {
  const int nb = h.n / h.b;
  const uint a = pndfGroupAngular(h, f), b = a + uint(h.b * h.rank);
  const uint sa = b + uint(h.b * h.rank), sb = sa + uint((h.b + 1) * h.rank);
  const ivec2 b0 = ivec2(x0) / h.b, b1 = min(ivec2(nb - 1), ivec2(ceil(x1)) / h.b);
  float total = 0.0;
  for (int by = b0.y; by <= b1.y; ++by)
    for (int bx = b0.x; bx <= b1.x; ++bx) {
      uint row;
      if (!pndfBlockRow(h, f, by * nb + bx, row)) continue;
      const vec2 origin = vec2(bx, by) * float(h.b);
      const vec2 lo = clamp(x0 - origin, 0.0, float(h.b)), hi = clamp(x1 - origin, 0.0, float(h.b));
      if (!(hi.x > lo.x && hi.y > lo.y)) continue;
      for (int r = 0; r < h.rank; ++r)
        total += (pndfPrefix(h, sa, a, hi.x, r) - pndfPrefix(h, sa, a, lo.x, r)) *
                 (pndfPrefix(h, sb, b, hi.y, r) - pndfPrefix(h, sb, b, lo.y, r)) * pndfValues[row + uint(r)];
    }
  return max(total, 0.0);
}

// The same integral from the box's four corners through the footprint's box prefix tables
// (src/prefilter/box_prefix_tables.hpp explains them; its box_prefix_range_sum is this one's twin):
// R products per corner whatever the box's size. Differences of table entries come first, so that
// a box inside one block row or column cancels exactly. Corner ij: x_i, y_j.
float pndfPixelRangeSumByCorners(PndfHeader h, uint f, vec2 x0, vec2 x1) {
  const int nb = h.n / h.b;
  const uint a = pndfGroupAngular(h, f), b = a + uint(h.b * h.rank);
  const uint sa = b + uint(h.b * h.rank), sb = sa + uint((h.b + 1) * h.rank);
  const ivec2 block0 = min(ivec2(x0) / h.b, ivec2(nb - 1)), block1 = min(ivec2(x1) / h.b, ivec2(nb - 1));
  const vec2 in0 = x0 - vec2(block0 * h.b), in1 = x1 - vec2(block1 * h.b);
  const int bit00 = block0.y * nb + block0.x, bit10 = block0.y * nb + block1.x;
  const int bit01 = block1.y * nb + block0.x, bit11 = block1.y * nb + block1.x;
  const uint stride = uint(2 * h.rank + 1), table = h.tables + f * uint(nb * nb) * stride;
  const uint t00 = table + uint(bit00) * stride, t10 = table + uint(bit10) * stride;
  const uint t01 = table + uint(bit01) * stride, t11 = table + uint(bit11) * stride;
  uint row00, row10, row01, row11;  // each corner's long factor
  const float k00 = pndfKeptRow(h, f, bit00, row00), k10 = pndfKeptRow(h, f, bit10, row10);
  const float k01 = pndfKeptRow(h, f, bit01, row01), k11 = pndfKeptRow(h, f, bit11, row11);
  float total = (pndfValues[t11] - pndfValues[t01]) - (pndfValues[t10] - pndfValues[t00]);
  if (PNDF_VECTOR_LOADS) {
    for (int r = 0; r < PNDF_FIXED_RANK; r += 4) {
      const vec4 pa0 = pndfPrefix4(h, sa, a, in0.x, r), pa1 = pndfPrefix4(h, sa, a, in1.x, r);
      const vec4 pb0 = pndfPrefix4(h, sb, b, in0.y, r), pb1 = pndfPrefix4(h, sb, b, in1.y, r);
      const uint u = uint(1 + r), l = uint(1 + h.rank + r);
      total += dot(pa1 * pb1, k11 * pndfRow4(row11, r)) - dot(pa0 * pb1, k01 * pndfRow4(row01, r)) -
               dot(pa1 * pb0, k10 * pndfRow4(row10, r)) + dot(pa0 * pb0, k00 * pndfRow4(row00, r)) +
               dot(pa1, pndfFloats4(t11 + u) - pndfFloats4(t10 + u)) + dot(pa0, pndfFloats4(t00 + u) - pndfFloats4(t01 + u)) +
               dot(pb1, pndfFloats4(t11 + l) - pndfFloats4(t01 + l)) + dot(pb0, pndfFloats4(t00 + l) - pndfFloats4(t10 + l));
    }
    return max(total, 0.0);
  }
  for (int r = 0; r < h.rank; ++r) {
    const float pa0 = pndfPrefix(h, sa, a, in0.x, r), pa1 = pndfPrefix(h, sa, a, in1.x, r);
    const float pb0 = pndfPrefix(h, sb, b, in0.y, r), pb1 = pndfPrefix(h, sb, b, in1.y, r);
    const uint u = uint(1 + r), l = uint(1 + h.rank + r);
    total += pa1 * pb1 * k11 * pndfValues[row11 + uint(r)] - pa0 * pb1 * k01 * pndfValues[row01 + uint(r)] -
             pa1 * pb0 * k10 * pndfValues[row10 + uint(r)] + pa0 * pb0 * k00 * pndfValues[row00 + uint(r)] +
             pa1 * (pndfValues[t11 + u] - pndfValues[t10 + u]) + pa0 * (pndfValues[t00 + u] - pndfValues[t01 + u]) +
             pb1 * (pndfValues[t11 + l] - pndfValues[t01 + l]) + pb0 * (pndfValues[t00 + l] - pndfValues[t10 + l]);
  }
  return max(total, 0.0);
}

// The level and position of a footprint N(centre, sigma^2) (texels) among the stored ones:
// trilinear (sec. 4.1): bilinear over the four nearest centres of the two levels around
// log2(sigma / sigma_0), clamped to the first and last level. A Wang tile's (partial) pyramid
// does not wrap: centres off its grid weigh 0; past its last level, the last level's footprint at
// the tile's centre times the share of the footprint on the tile over that footprint's share. Each level's cell is kept as
// scalars and its eight footprints are enumerated by pndfCorner, so that no array is indexed at
// run time in the loops over them (a GPU would keep such an array in local memory).
struct PndfLevelCell {
  uint first;     // the level's first footprint
  bool wraps;     // a map's grid wraps; a tile's does not
  ivec2 count;    // its footprints per axis
  ivec2 origin;   // the cell's lower corner (footprint grid coordinates, not yet wrapped)
  vec2 fraction;  // the centre's position in the cell
  float weight;   // the level's trilinear weight
};
struct PndfInterpolation {
  PndfLevelCell lower, upper;
};

PndfLevelCell pndfLevelCell(PndfHeader h, vec2 centre, int level, float levelWeight) {
  const ivec2 count = ivec2(pndfLevelWord(h, level, 0u), pndfLevelWord(h, level, 1u));
  const vec2 spacing = vec2(uintBitsToFloat(pndfLevelWord(h, level, 2u)), uintBitsToFloat(pndfLevelWord(h, level, 3u)));
  const vec2 origin = vec2(uintBitsToFloat(pndfLevelWord(h, level, 6u)), uintBitsToFloat(pndfLevelWord(h, level, 7u)));
  const vec2 g = (centre - origin) / spacing - 0.5;
  const vec2 g0 = floor(g);
  return PndfLevelCell(pndfLevelWord(h, level, 4u), !h.partial, count, ivec2(g0), g - g0, levelWeight);
}

// erf(x) (Abramowitz & Stegun 7.1.26, absolute error below 1.5e-7).
float pndfErf(float x) {
  const float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  const float y = 1.0 - t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429)))) *
                            exp(-x * x);
  return sign(x) * y;
}

// An element's standard deviation at k elements per texel and axis, 1.5 / (k sqrt 12) texels
// (position_normal_element_sigma).
float pndfElementSigma(int k) { return 1.5 / (float(k) * 3.4641016); }

// The share of N(centre, (sigma^2 + the elements' variance) I) on a partial pyramid's tile
// [0, size]^2 (PrefilteredNdf::tile_share).
float pndfTileShare(PndfHeader h, vec2 centre, float sigma) {
  const float element = pndfElementSigma(h.elementsPerTexel);
  const float s = sqrt(2.0 * (sigma * sigma + element * element));
  const vec2 share = 0.5 * vec2(pndfErf((h.size.x - centre.x) / s) - pndfErf(-centre.x / s),
                                pndfErf((h.size.y - centre.y) / s) - pndfErf(-centre.y / s));
  return share.x * share.y;
}

PndfInterpolation pndfInterpolation(PndfHeader h, vec2 centre, float sigma) {
  const int last = h.levels - 1;
  const float sigma0 = uintBitsToFloat(pndfLevelWord(h, 0, 5u));
  const float sigmaLast = uintBitsToFloat(pndfLevelWord(h, last, 5u));
  if (h.partial && sigma > sigmaLast) {
    const vec2 middle = 0.5 * h.size;  // a footprint's centre of the last level
    const float scale = h.topShare > 0.0 ? pndfTileShare(h, centre, sigma) / h.topShare : 0.0;
    return PndfInterpolation(pndfLevelCell(h, middle, last, scale), pndfLevelCell(h, middle, last, 0.0));
  }
  const float lambda = clamp(log2(max(sigma, 1e-9) / sigma0), 0.0, float(last));
  const int l0 = min(int(lambda), last);
  const float t = lambda - float(l0);
  return PndfInterpolation(pndfLevelCell(h, centre, l0, 1.0 - t), pndfLevelCell(h, centre, min(l0 + 1, last), t));
}

// Footprint q (q < 8: q / 4 the level, q % 4 the corner of its cell) of the interpolation, and
// its weight. A map's grid wraps around it (the map tiles); a Wang tile's stops.
uint pndfCorner(PndfInterpolation interpolation, int q, out float weight) {
  const PndfLevelCell c = q < 4 ? interpolation.lower : interpolation.upper;
  const ivec2 d = ivec2(q & 1, (q >> 1) & 1);
  const ivec2 g = c.origin + d;
  const ivec2 p = c.wraps ? floorMod(g, c.count) : clamp(g, ivec2(0), c.count - 1);
  const bool on = c.wraps || g == p;  // a tile's footprint off its grid sees none of it
  weight = on ? c.weight * (d.x == 1 ? c.fraction.x : 1.0 - c.fraction.x) * (d.y == 1 ? c.fraction.y : 1.0 - c.fraction.y)
              : 0.0;
  return c.first + uint(p.y * c.count.x + p.x);
}

vec2 pndfToPixels(PndfHeader h, vec2 s) { return (s + h.extent) * (float(h.n) / (2.0 * h.extent)); }

// P(s) of the footprint: pixels bilinearly interpolated (0 outside the image), never negative.
// Bilinear weights are separable, so per stored footprint the 2 x 2 pixels are summed in factor
// space: sum_r (w_i0 a(i0, r) + w_i1 a(i1, r)) (w_j0 b(j0, r) + w_j1 b(j1, r)) c(r) where they share
// a block (most of the time), each of the up to 4 blocks with its own c otherwise; 8 loads per rank.
float pndfDensity(PndfHeader h, vec2 centre, float sigma, vec2 s) {
  const PndfInterpolation interpolation = pndfInterpolation(h, centre, sigma);
  const vec2 x = pndfToPixels(h, s) - 0.5;
  const vec2 fr = x - floor(x);
  const ivec2 p0 = ivec2(floor(x)), p1 = p0 + 1;
  // Pixels outside the image weigh 0 (and read a pixel inside it).
  const vec2 w0 = mix(vec2(0.0), 1.0 - fr, equal(p0, clamp(p0, 0, h.n - 1)));
  const vec2 w1 = mix(vec2(0.0), fr, equal(p1, clamp(p1, 0, h.n - 1)));
  const ivec2 q0 = clamp(p0, 0, h.n - 1), q1 = clamp(p1, 0, h.n - 1);
  const int nb = h.n / h.b;
  const ivec2 block0 = q0 / h.b, block1 = q1 / h.b;
  const ivec2 in0 = q0 - block0 * h.b, in1 = q1 - block1 * h.b;
  float sum = 0.0;
  for (int q = 0; q < 8; ++q) {
    float weight;
    const uint footprint = pndfCorner(interpolation, q, weight);
    if (weight <= 0.0) continue;
    const uint a = pndfGroupAngular(h, footprint), b = a + uint(h.b * h.rank);
    uint row00, row10, row01, row11;
    const float k00 = weight * pndfKeptRow(h, footprint, block0.y * nb + block0.x, row00);
    const float k10 = weight * pndfKeptRow(h, footprint, block0.y * nb + block1.x, row10);
    const float k01 = weight * pndfKeptRow(h, footprint, block1.y * nb + block0.x, row01);
    const float k11 = weight * pndfKeptRow(h, footprint, block1.y * nb + block1.x, row11);
    const uint ai0 = a + uint(in0.x * h.rank), ai1 = a + uint(in1.x * h.rank);
    const uint bj0 = b + uint(in0.y * h.rank), bj1 = b + uint(in1.y * h.rank);
    if (PNDF_VECTOR_LOADS) {
      for (int r = 0; r < PNDF_FIXED_RANK; r += 4) {
        const vec4 x0 = w0.x * pndfRow4(ai0, r), x1 = w1.x * pndfRow4(ai1, r);
        const vec4 y0 = w0.y * pndfRow4(bj0, r), y1 = w1.y * pndfRow4(bj1, r);
        sum += dot(x0, y0 * k00 * pndfRow4(row00, r) + y1 * k01 * pndfRow4(row01, r)) +
               dot(x1, y0 * k10 * pndfRow4(row10, r) + y1 * k11 * pndfRow4(row11, r));
      }
      continue;
    }
    for (int r = 0; r < h.rank; ++r) {
      const uint u = uint(r);
      const float x0 = w0.x * pndfValues[ai0 + u], x1 = w1.x * pndfValues[ai1 + u];
      const float y0 = w0.y * pndfValues[bj0 + u], y1 = w1.y * pndfValues[bj1 + u];
      sum += x0 * (y0 * k00 * pndfValues[row00 + u] + y1 * k01 * pndfValues[row01 + u]) +
             x1 * (y0 * k10 * pndfValues[row10 + u] + y1 * k11 * pndfValues[row11 + u]);
    }
  }
  return max(sum, 0.0);  // a CP reconstruction can dip below 0 where the NDF is near it
}

// The mean of P over the box [lo, hi] of s (0 outside the image). `prefixTables` (a constant of the
// caller's, so that one path is compiled): through the box prefix tables, which the pyramid must
// have been packed with, at a constant cost; otherwise block by block (eq. 7).
float pndfRangeMean(PndfHeader h, vec2 centre, float sigma, vec2 lo, vec2 hi, bool prefixTables) {
  const vec2 size = hi - lo;
  if (!(size.x > 0.0 && size.y > 0.0)) return pndfDensity(h, centre, sigma, 0.5 * (lo + hi));
  const vec2 x0 = clamp(pndfToPixels(h, lo), 0.0, float(h.n)), x1 = clamp(pndfToPixels(h, hi), 0.0, float(h.n));
  if (!(x1.x > x0.x && x1.y > x0.y)) return 0.0;
  const PndfInterpolation interpolation = pndfInterpolation(h, centre, sigma);
  float sum = 0.0;
  for (int q = 0; q < 8; ++q) {
    float weight;
    const uint footprint = pndfCorner(interpolation, q, weight);
    if (weight > 0.0)
      sum += weight * (prefixTables ? pndfPixelRangeSumByCorners(h, footprint, x0, x1) : pndfPixelRangeSum(h, footprint, x0, x1));
  }
  const float pixel = 2.0 * h.extent / float(h.n);
  return sum * pixel * pixel / (size.x * size.y);
}
