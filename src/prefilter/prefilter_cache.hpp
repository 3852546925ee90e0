#pragma once
// Precomputed pyramids kept on disk: a pyramid is rebuilt only when its map's texels, its
// intrinsic roughness or a setting changes (the key hashes all of them and the entry repeats the
// settings' text, compared when read). An entry is core/cache_entry.hpp's frame (checksum and size)
// around PrefilteredNdf::write's bytes; one that is damaged, inconsistent (check_consistent()),
// foreign or not a regular file is reported on stderr and rebuilt (and a special file is left as
// it is).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// The entry format's magic (its version: 2 has the checksum frame, 3 levels' origins and Wang tiles' pyramids).
inline constexpr std::string_view kPrefilteredNdfMagic = "GLPNDF3\n";
/// The line an entry starts with: what it was built from (the map's size, its Wang tiling and the
/// tile, the roughness, the settings). `tile` >= 0: that Wang tile's pyramid (map.wang set).
std::string prefiltered_ndf_built_from(const NormalMap& map, double intrinsic_roughness,
                                       const PrefilterSettings& settings, int tile = -1);

/// The pyramid's cache file name (without directory) for this map (and tile), roughness and settings.
std::string prefiltered_ndf_key(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings,
                                int tile = -1);

/// The cached pyramid, or a new one (precomputed, then stored) when there is none. An empty
/// `cache_directory` disables the cache. `tile` >= 0: that Wang tile's pyramid
/// (prefilter/wang_tile_pyramids.hpp).
PrefilteredNdf load_or_precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                                  const PrefilterSettings& settings,
                                                  const std::filesystem::path& cache_directory, int tile = -1);

/// Every pyramid of a map: its own, or its 16 Wang tiles' (by tile).
std::vector<PrefilteredNdf> load_or_precompute_pyramids(const NormalMap& map, double intrinsic_roughness,
                                                        const PrefilterSettings& settings,
                                                        const std::filesystem::path& cache_directory);

}  // namespace glintlab
