#pragma once
// Deng et al. 2022's pyramids on a surface of Wang tiles (sec. 5.5, fig. 12): one pyramid per tile
// of *partial* footprints. A footprint's NDF on the surface is the sum over its elements; grouped by
// the tile each element lies in, it is the sum over the cells the footprint reaches of that cell's
// tile's share, which depends only on the tile and on the footprint's centre relative to the cell.
// So each tile stores the images of the footprints centred on a grid that covers the tile and
// reaches past it by a footprint's reach (the paper's "centers outside the Wang tiles"); each image
// sums the tile's elements only, over the weight of every element of the plane the footprint
// reaches, so that the images of the cells' tiles add up to the surface's NDF (PrefilteredNdf::partial).
//
// A tile's border elements are made from the texels around it where it lies on the surface, the
// skirt: across an edge those are the edge's diamond's continuation in the input, the same wherever
// the tile lies (scene/normal_maps/wang_tiles.hpp); only the few texels diagonal to a corner depend
// on the neighbouring tile. The skirt is read where the lattice first puts the tile.
#include <array>
#include <functional>
#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "prefilter/ndf_image.hpp"
#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// Tile `tile` (0 .. 15) of a map of Wang tiles (map.wang set): its pyramid of partial footprints,
/// levels sigma_0 2^l from sigma_0 = base_stride up to the first at least the tile's size. The NDF
/// grid is the whole atlas's (every tile's the same). Throws InputError for a plain map.
PrefilteredNdf precompute_wang_tile_pyramid(const NormalMap& map, int tile, double intrinsic_roughness,
                                            const PrefilterSettings& settings);

/// The cell where the lattice of `map` first puts `tile` (row by row over its period), or {-1, -1}
/// where it never does (its pyramid is then made from its atlas place, and no query reads it).
std::array<int, 2> wang_tile_placement(const NormalMap& map, int tile);

/// The levels of a tile's pyramid (no footprint yet): sigma_0 2^l (sigma_0 = base_stride) up to the
/// first at least the tile's size, centres sigma_0 2^l apart, symmetric about the tile's centre
/// (one at it) and reaching wang_footprint_reach past the tile on every side.
std::vector<PrefilterLevel> wang_tile_levels(const PrefilterSettings& settings, int tile_size);

/// An upper bound of the 16 tiles' pyramids' packed bytes (prefiltered_ndf_bytes_bound's).
std::uint64_t wang_tile_pyramids_bytes_bound(const PrefilterSettings& settings, int tile_size, bool box_prefix_tables);

/// How far past a cell a footprint of deviation sigma (texels) reaches it: 3 deviations of the
/// footprint widened by an element (the elements' truncation) and a texel.
double wang_footprint_reach(double sigma, int elements_per_texel);

/// Calls `visit(cell, tile, local_centre)` for every cell of the surface of `map` (map.wang set)
/// that a footprint N(centre, sigma^2 I) reaches: its tile and the centre relative to the cell.
void for_each_reached_tile(const NormalMap& map, glm::dvec2 centre, double sigma, int elements_per_texel,
                           const std::function<void(std::array<std::int64_t, 2>, int, glm::dvec2)>& visit);

/// The exact NDF image of N(centre, sigma^2 I) on a map's surface (plain or of Wang tiles, any place:
/// it repeats): Yan 2016's sum over the elements of a window of the surface around the footprint,
/// wide enough for its reach. What the tiles' pyramids are measured against.
NdfImage exact_surface_image(const NormalMap& map, double intrinsic_roughness, int elements_per_texel, glm::dvec2 centre,
                             double sigma, const NdfGrid& grid);

/// P(s) of the footprint N(centre, sigma^2 I) on the surface: the sum of the reached cells' tiles'
/// partial densities (`tiles`: the 16 pyramids, by tile). The CPU twin of the shaders' query
/// (shaders/glints/normal-map/wang_tile_queries.glsl).
double wang_tiles_density(const NormalMap& map, std::span<const PrefilteredNdf> tiles, glm::dvec2 centre, double sigma,
                          glm::dvec2 s);

}  // namespace glintlab
