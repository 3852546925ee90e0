#pragma once
// Precomputed pyramids kept on disk: a pyramid is rebuilt only when its map's texels, its
// intrinsic roughness or a setting changes (the key hashes all of them and the file repeats the
// settings' text, compared when read). Files are written atomically; a corrupt one is rebuilt.
#include <filesystem>
#include <string>

#include "prefilter/prefiltered_ndf.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// The pyramid's cache file name (without directory) for this map, roughness and settings.
std::string prefiltered_ndf_key(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings);

/// The cached pyramid, or a new one (precomputed, then stored) when there is none. An empty
/// `cache_directory` disables the cache.
PrefilteredNdf load_or_precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                                  const PrefilterSettings& settings,
                                                  const std::filesystem::path& cache_directory);

}  // namespace glintlab
