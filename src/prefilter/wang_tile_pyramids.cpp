#include "prefilter/wang_tile_pyramids.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "prefilter/position_normal.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

namespace glintlab {

namespace {

/// Texels of skirt around the tile: its border elements' neighbours (k = 2 reads one texel past
/// the element's cell, k = 1 one texel along each axis).
constexpr int kSkirt = 2;

}  // namespace

std::array<int, 2> wang_tile_placement(const NormalMap& map, int tile) {
  const WangTiling& w = *map.wang;
  const WangLattice lattice(w.seed, w.tiles);
  for (int j = 0; j < w.tiles; ++j)
    for (int i = 0; i < w.tiles; ++i)
      if (lattice.cell(i, j).tile() == tile) return {i, j};
  return {-1, -1};
}

PrefilteredNdf precompute_wang_tile_pyramid(const NormalMap& map, int tile, double intrinsic_roughness,
                                            const PrefilterSettings& settings) {
  settings.validate();
  if (!map.wang) throw InputError("a plain map has one pyramid (precompute_prefiltered_ndf), not one per Wang tile");
  if (tile < 0 || tile > 15) throw InputError("Wang tile " + std::to_string(tile) + "; allowed: 0 .. 15");
  const auto start = std::chrono::steady_clock::now();
  const int t = map.wang->tile_size, k = settings.elements_per_texel;
  // The tile and its skirt, as the surface has them where the tile lies (its atlas place, with the
  // atlas's own neighbours, where the lattice never puts it: then no query reads the pyramid).
  NormalMap atlas = map;  // the stored texels as a plain map
  atlas.wang.reset();
  const std::array<int, 2> cell = wang_tile_placement(map, tile);
  const bool placed = cell[0] >= 0;
  const std::int64_t x0 = placed ? std::int64_t{t} * cell[0] : (tile & 3) * t, y0 = placed ? std::int64_t{t} * cell[1] : (tile >> 2) * t;
  const NormalMap region = surface_window(placed ? map : atlas, x0 - kSkirt, y0 - kSkirt, t + 2 * kSkirt, t + 2 * kSkirt);
  const PositionNormalDistribution pnd(region, intrinsic_roughness, k);
  const ElementWindow window{.lo = glm::ivec2(kSkirt * k), .hi = glm::ivec2((kSkirt + t) * k)};
  // One NDF grid for all 16 tiles: the atlas's.
  const double extent = PositionNormalDistribution(atlas, intrinsic_roughness, k).suggested_extent();
  PrefilteredNdf out = empty_pyramid(settings, extent, intrinsic_roughness);
  out.width = t;
  out.height = t;
  out.partial = true;
  const std::vector<PrefilterLevel> levels = wang_tile_levels(settings, t);
  const LevelLayout layout = [&](int l) -> std::optional<PrefilterLevel> {
    return l < static_cast<int>(levels.size()) ? std::optional(levels[static_cast<std::size_t>(l)]) : std::nullopt;
  };
  build_levels(out, pnd, &window, glm::dvec2(kSkirt), layout, false);
  out.precompute_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<PrefilterLevel> wang_tile_levels(const PrefilterSettings& settings, int tile_size) {
  // Level l: sigma_0 2^l up to the first at least the tile's size, centres sigma_0 2^l apart,
  // symmetric about the tile's centre (one at it) and reaching a footprint's reach past the tile.
  std::vector<PrefilterLevel> levels;
  for (int l = 0; l < settings.max_levels && (levels.empty() || levels.back().sigma < tile_size); ++l) {
    PrefilterLevel level;
    level.sigma = settings.base_stride * std::ldexp(1.0, l);
    const double spacing = level.sigma;
    const int half = static_cast<int>(std::ceil((0.5 * tile_size + wang_footprint_reach(level.sigma, settings.elements_per_texel)) / spacing));
    level.nx = level.ny = 2 * half + 1;
    level.spacing = glm::dvec2(spacing);
    level.origin = glm::dvec2(0.5 * tile_size - (half + 0.5) * spacing);
    levels.push_back(level);
  }
  return levels;
}

std::uint64_t wang_tile_pyramids_bytes_bound(const PrefilterSettings& settings, int tile_size, bool box_prefix_tables) {
  std::vector<std::array<std::uint64_t, 2>> sizes;
  for (const PrefilterLevel& l : wang_tile_levels(settings, tile_size))
    sizes.push_back({static_cast<std::uint64_t>(l.nx), static_cast<std::uint64_t>(l.ny)});
  return 16 * (pyramid_bytes_bound(settings, sizes, box_prefix_tables) + 4);
}

double wang_footprint_reach(double sigma, int elements_per_texel) {
  const double element = position_normal_element_sigma(elements_per_texel);
  return kElementTruncation * std::sqrt(sigma * sigma + element * element) + 1.0;
}

void for_each_reached_tile(const NormalMap& map, glm::dvec2 centre, double sigma, int elements_per_texel,
                           const std::function<void(std::array<std::int64_t, 2>, int, glm::dvec2)>& visit) {
  const WangTiling& w = *map.wang;
  const WangLattice lattice(w.seed, w.tiles);
  const double reach = wang_footprint_reach(sigma, elements_per_texel), t = w.tile_size;
  const auto i0 = static_cast<std::int64_t>(std::floor((centre.x - reach) / t));
  const auto i1 = static_cast<std::int64_t>(std::floor((centre.x + reach) / t));
  const auto j0 = static_cast<std::int64_t>(std::floor((centre.y - reach) / t));
  const auto j1 = static_cast<std::int64_t>(std::floor((centre.y + reach) / t));
  for (std::int64_t j = j0; j <= j1; ++j)
    for (std::int64_t i = i0; i <= i1; ++i)
      visit({i, j}, lattice.cell(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)).tile(),
            centre - glm::dvec2(static_cast<double>(i), static_cast<double>(j)) * t);
}

double wang_tiles_density(const NormalMap& map, std::span<const PrefilteredNdf> tiles, glm::dvec2 centre, double sigma,
                          glm::dvec2 s) {
  double sum = 0.0;
  for_each_reached_tile(map, centre, sigma, tiles.front().settings.elements_per_texel,
                        [&](std::array<std::int64_t, 2>, int tile, glm::dvec2 local) {
                          sum += tiles[static_cast<std::size_t>(tile)].density(local, sigma, s);
                        });
  return sum;
}

NdfImage exact_surface_image(const NormalMap& map, double intrinsic_roughness, int elements_per_texel, glm::dvec2 centre,
                             double sigma, const NdfGrid& grid) {
  const int half = static_cast<int>(std::ceil(wang_footprint_reach(sigma, elements_per_texel))) + 4;
  const glm::dvec2 corner = glm::floor(centre) - static_cast<double>(half);
  const NormalMap window = surface_window(map, static_cast<std::int64_t>(corner.x), static_cast<std::int64_t>(corner.y),
                                          2 * half, 2 * half);
  return PositionNormalDistribution(window, intrinsic_roughness, elements_per_texel)
      .image(Footprint::isotropic(centre - corner, sigma), grid);
}

}  // namespace glintlab
