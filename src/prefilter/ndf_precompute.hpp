#pragma once
// Building a PrefilteredNdf (Deng et al. 2022, sec. 4.1-4.2): NDF images of a pyramid of Gaussian
// footprints computed bottom-up from Yan 2016's elements, stopping when a level agrees with the
// one below; each level's footprints grouped by position, their non-empty angular blocks stacked
// into one tensor per group and CP-decomposed. Groups are independent and run on every core.
#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// Precomputes the pyramid of `map` with intrinsic roughness sigma_r. Reports progress through
/// report_generation_progress (a bar on a terminal). Throws InputError for bad settings.
PrefilteredNdf precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                          const PrefilterSettings& settings);

}  // namespace glintlab
