#include "prefilter/prefilter_cache.hpp"

#include <cstdio>
#include <sstream>

#include "core/cache_entry.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/hash.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "prefilter/wang_tile_pyramids.hpp"

namespace glintlab {

namespace {
/// Bump when precompute_prefiltered_ndf would give other values for the same inputs.
constexpr std::uint32_t kPrefilterVersion = 2;
std::string header_text(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings, int tile) {
  std::ostringstream s;
  s.precision(17);
  s << "version=" << kPrefilterVersion << " map=" << map.width << "x" << map.height;
  if (map.wang)
    s << " wang_tiles=" << map.wang->tile_size << "," << map.wang->tiles << "," << map.wang->seed << " tile=" << tile;
  s << " intrinsic_roughness=" << intrinsic_roughness << " " << settings.describe();
  return s.str();
}

/// Why a pyramid read from an entry is not the one asked for, or empty. The header line already
/// matched; these are the same facts in the binary part, which a damaged entry can contradict.
std::string mismatch(const PrefilteredNdf& p, const NormalMap& map, double intrinsic_roughness,
                     const PrefilterSettings& settings) {
  const int width = map.wang ? map.wang->tile_size : map.width, height = map.wang ? map.wang->tile_size : map.height;
  if (p.width != width || p.height != height) return "its map size is not the map's";
  if (p.partial != map.wang.has_value()) return "it is not the kind of pyramid the map has";
  if (p.intrinsic_roughness != intrinsic_roughness) return "its intrinsic roughness differs";
  // ndf_resolution and block_size 0 ask for a grid chosen from the map (choose_ndf_grid).
  const auto differs = [](int stored, int asked) { return asked != 0 && stored != asked; };
  if (p.settings.elements_per_texel != settings.elements_per_texel ||
      differs(p.settings.ndf_resolution, settings.ndf_resolution) || differs(p.settings.block_size, settings.block_size) ||
      p.settings.cp.rank != settings.cp.rank)
    return "its settings differ from its header";
  if (static_cast<int>(p.levels.size()) > settings.max_levels) return "it has more levels than allowed";
  return {};
}
}  // namespace

std::string prefiltered_ndf_built_from(const NormalMap& map, double intrinsic_roughness,
                                      const PrefilterSettings& settings, int tile) {
  return header_text(map, intrinsic_roughness, settings, tile);
}

std::string prefiltered_ndf_key(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings,
                                int tile) {
  Hasher h;
  h.text(header_text(map, intrinsic_roughness, settings, tile));
  h.span(std::span<const glm::vec3>(map.normals));
  char name[40];
  std::snprintf(name, sizeof name, "pndf-%016llx.bin", static_cast<unsigned long long>(h.digest()));
  return name;
}

PrefilteredNdf load_or_precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                                  const PrefilterSettings& settings,
                                                  const std::filesystem::path& cache_directory, int tile) {
  if ((tile >= 0) != map.wang.has_value())
    throw InputError(map.wang ? "a map of Wang tiles has a pyramid per tile: name the tile"
                              : "a plain map has no Wang tiles' pyramids");
  const std::string header = header_text(map, intrinsic_roughness, settings, tile);
  const std::filesystem::path path =
      cache_directory.empty()
          ? std::filesystem::path()
          : cache_directory / "prefiltered-ndf" / prefiltered_ndf_key(map, intrinsic_roughness, settings, tile);
  bool replaceable = true;
  if (!path.empty()) {
    CacheEntryRead entry = read_cache_entry(path, kPrefilteredNdfMagic, header, kMaxBinaryFileBytes);
    std::string problem = std::move(entry.problem);
    if (entry.payload) {
      try {
        std::istringstream in(*entry.payload);
        PrefilteredNdf p = PrefilteredNdf::read(in);
        problem = mismatch(p, map, intrinsic_roughness, settings);
        if (problem.empty()) {
          // The settings asked for, with the grid the entry was made with where they asked for
          // one chosen from the map (0).
          const int resolution = p.settings.ndf_resolution, block_size = p.settings.block_size;
          p.settings = settings;
          p.settings.ndf_resolution = resolution;
          p.settings.block_size = block_size;
          return p;
        }
      } catch (const RuntimeFailure& e) {
        problem = e.what();
      }
    }
    if (!problem.empty()) warn_rebuilding_cache_entry(path, problem);
    const FileKind kind = file_kind(path, false);
    replaceable = kind == FileKind::missing || kind == FileKind::regular;
  }
  PrefilteredNdf p = tile >= 0 ? precompute_wang_tile_pyramid(map, tile, intrinsic_roughness, settings)
                                : precompute_prefiltered_ndf(map, intrinsic_roughness, settings);
  if (!path.empty() && replaceable) {
    std::ostringstream out;
    p.write(out);
    if (const std::string failed = write_cache_entry(path, kPrefilteredNdfMagic, header, out.str()); !failed.empty())
      std::fprintf(stderr, "glintlab: warning: cannot store the pyramid in the cache: %s\n", failed.c_str());
  }
  return p;
}

std::vector<PrefilteredNdf> load_or_precompute_pyramids(const NormalMap& map, double intrinsic_roughness,
                                                        const PrefilterSettings& settings,
                                                        const std::filesystem::path& cache_directory) {
  std::vector<PrefilteredNdf> out;
  if (!map.wang) {
    out.push_back(load_or_precompute_prefiltered_ndf(map, intrinsic_roughness, settings, cache_directory));
    return out;
  }
  for (int tile = 0; tile < 16; ++tile)
    out.push_back(load_or_precompute_prefiltered_ndf(map, intrinsic_roughness, settings, cache_directory, tile));
  return out;
}

}  // namespace glintlab
