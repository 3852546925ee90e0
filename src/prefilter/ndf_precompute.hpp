#pragma once
// Building a PrefilteredNdf (Deng et al. 2022, sec. 4.1-4.2): NDF images of a pyramid of Gaussian
// footprints computed bottom-up from Yan 2016's elements, stopping when a level agrees with the
// one below; each level's footprints grouped by position, their non-empty angular blocks stacked
// into one tensor per group and CP-decomposed. Groups are independent and run on every core.
#include <functional>
#include <optional>

#include "prefilter/position_normal.hpp"
#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// Precomputes the pyramid of `map` (a plain map; a map of Wang tiles has one per tile:
/// prefilter/wang_tile_pyramids.hpp) with intrinsic roughness sigma_r. Reports progress through
/// report_generation_progress (a bar on a terminal). Throws InputError for bad settings.
PrefilteredNdf precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                          const PrefilterSettings& settings);

// The builder both kinds of pyramid share:

/// A pyramid with no level yet: `settings` with the NDF grid chosen for `extent` (choose_ndf_grid).
PrefilteredNdf empty_pyramid(const PrefilterSettings& settings, double extent, double intrinsic_roughness);

/// Where a level's footprints lie and how wide they are; nullopt past the pyramid's last level.
using LevelLayout = std::function<std::optional<PrefilterLevel>(int level)>;

/// Appends the levels `layout` gives to `out` (grid, settings and map fields set): each level's
/// footprints' images from `pnd` (centred at the level's centres + shift in pnd's map coordinates;
/// only the `window`'s elements where one is given), grouped and CP-compressed, on every core.
/// `stop_test`: stop at the first level that differs from the level below by less than the
/// settings' tolerance (sec. 4.1); also after a level of one footprint, or max_levels.
void build_levels(PrefilteredNdf& out, const PositionNormalDistribution& pnd, const ElementWindow* window,
                  glm::dvec2 shift, const LevelLayout& layout, bool stop_test);

}  // namespace glintlab
