#include "prefilter/prefilter_cache.hpp"

#include <cstdio>
#include <sstream>

#include "core/cache_entry.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/hash.hpp"
#include "prefilter/ndf_precompute.hpp"

namespace glintlab {

namespace {
/// Bump when precompute_prefiltered_ndf would give other values for the same inputs.
constexpr std::uint32_t kPrefilterVersion = 1;
std::string header_text(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings) {
  std::ostringstream s;
  s.precision(17);
  s << "version=" << kPrefilterVersion << " map=" << map.width << "x" << map.height
    << " intrinsic_roughness=" << intrinsic_roughness << " " << settings.describe();
  return s.str();
}

/// Why a pyramid read from an entry is not the one asked for, or empty. The header line already
/// matched; these are the same facts in the binary part, which a damaged entry can contradict.
std::string mismatch(const PrefilteredNdf& p, const NormalMap& map, double intrinsic_roughness,
                     const PrefilterSettings& settings) {
  if (p.width != map.width || p.height != map.height) return "its map size is not the map's";
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
                                      const PrefilterSettings& settings) {
  return header_text(map, intrinsic_roughness, settings);
}

std::string prefiltered_ndf_key(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings) {
  Hasher h;
  h.text(header_text(map, intrinsic_roughness, settings));
  h.span(std::span<const glm::vec3>(map.normals));
  char name[40];
  std::snprintf(name, sizeof name, "pndf-%016llx.bin", static_cast<unsigned long long>(h.digest()));
  return name;
}

PrefilteredNdf load_or_precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                                  const PrefilterSettings& settings,
                                                  const std::filesystem::path& cache_directory) {
  const std::string header = header_text(map, intrinsic_roughness, settings);
  const std::filesystem::path path =
      cache_directory.empty() ? std::filesystem::path()
                              : cache_directory / "prefiltered-ndf" / prefiltered_ndf_key(map, intrinsic_roughness, settings);
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
  PrefilteredNdf p = precompute_prefiltered_ndf(map, intrinsic_roughness, settings);
  if (!path.empty() && replaceable) {
    std::ostringstream out;
    p.write(out);
    if (const std::string failed = write_cache_entry(path, kPrefilteredNdfMagic, header, out.str()); !failed.empty())
      std::fprintf(stderr, "glintlab: warning: cannot store the pyramid in the cache: %s\n", failed.c_str());
  }
  return p;
}

}  // namespace glintlab
