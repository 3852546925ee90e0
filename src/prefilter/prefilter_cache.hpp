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

#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// The entry format's magic (its version: 2 has the checksum frame, 3 levels' origins and Wang tiles' pyramids).
inline constexpr std::string_view kPrefilteredNdfMagic = "GLPNDF3\n";
/// The line an entry starts with: what it was built from (the map's size, the roughness, the settings).
std::string prefiltered_ndf_built_from(const NormalMap& map, double intrinsic_roughness,
                                       const PrefilterSettings& settings);

/// The pyramid's cache file name (without directory) for this map, roughness and settings.
std::string prefiltered_ndf_key(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings);

/// The cached pyramid, or a new one (precomputed, then stored) when there is none. An empty
/// `cache_directory` disables the cache.
PrefilteredNdf load_or_precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                                  const PrefilterSettings& settings,
                                                  const std::filesystem::path& cache_directory);

}  // namespace glintlab
