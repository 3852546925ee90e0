#pragma once
// The pyramids of a scene's materials packed into the two storage buffers the GPU query reads
// (shaders/glints/normal-map/prefiltered_ndf.glsl): `records`, of uint words, and `values`, of floats.
//
// records: word m (m < max_materials) holds material m's header offset, or kNoPrefilteredNdf; for
//   a material whose map is of Wang tiles, the offset of 16 words, its tiles' header offsets.
//   header at H: [0] levels, [1] N, [2] B, [3] R, [4] extent (float bits), [5] first word of the
//   footprint records, [6] first word of the group offsets, [7] first float of the angular
//   factors, [8] first float of the long factor's rows, [9] map width, [10] map height, [11] first float of the box prefix
//   tables (src/prefilter/box_prefix_tables.hpp), or kNoPrefilteredNdf where they were not packed,
//   [12] 1 for a Wang tile's pyramid (PrefilteredNdf::partial), else 0, [13] its elements per texel
//   (the images' source), [14] a tile's share of its last level's footprint at its centre
//   (PrefilteredNdf::tile_share, float bits; 0 for a map's), [15] 0;
//   then per level l at H + 16 + 8 l: nx, ny, spacing.x, spacing.y (float bits), first footprint,
//   sigma, origin.x, origin.y (float bits).
//   footprint f: 4 words (mask_lo, mask_hi, first row, group); group g: its angular offset.
// values: each material's angular factors (a, b, SA, SB per group), then its rows, then (if packed)
//   its box prefix tables, (N/B)^2 (2R + 1) floats per footprint; each of the three starts on a
//   multiple of 4 floats (zeros between), so that with R a multiple of 4 the factors' rows are
//   aligned vec4s.
#include <cstdint>
#include <span>
#include <vector>

#include "prefilter/prefiltered_ndf.hpp"

namespace glintlab {

inline constexpr std::uint32_t kNoPrefilteredNdf = 0xffffffffu;
inline constexpr int kPrefilteredNdfHeaderWords = 16;
inline constexpr int kPrefilteredNdfLevelWords = 8;

struct PrefilteredNdfBuffers {
  std::vector<std::uint32_t> records;
  std::vector<float> values;
};

/// `per_material[m]`: material m's pyramids: none, its map's, or its 16 Wang tiles' (by tile);
/// `box_prefix_tables`: whether to derive and pack the tables of constant-cost box queries. Throws
/// RuntimeFailure past 2^32 words.
PrefilteredNdfBuffers pack_prefiltered_ndfs(std::span<const std::vector<const PrefilteredNdf*>> per_material,
                                            int max_materials, bool box_prefix_tables = true);
/// One pyramid (or none) per material.
PrefilteredNdfBuffers pack_prefiltered_ndfs(std::span<const PrefilteredNdf* const> per_material, int max_materials,
                                            bool box_prefix_tables = true);

}  // namespace glintlab
