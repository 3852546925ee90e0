#include "prefilter/prefilter_cache.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "prefilter/ndf_precompute.hpp"

namespace glintlab {

namespace {
/// Bump when precompute_prefiltered_ndf would give other values for the same inputs.
constexpr std::uint32_t kPrefilterVersion = 1;
constexpr char kMagic[8] = {'G', 'L', 'P', 'N', 'D', 'F', '1', '\n'};

std::string header_text(const NormalMap& map, double intrinsic_roughness, const PrefilterSettings& settings) {
  std::ostringstream s;
  s.precision(17);
  s << "version=" << kPrefilterVersion << " map=" << map.width << "x" << map.height
    << " intrinsic_roughness=" << intrinsic_roughness << " " << settings.describe();
  return s.str();
}
}  // namespace

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
  if (!path.empty()) {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      try {
        char magic[8];
        std::string text;
        if (in.read(magic, 8) && std::equal(magic, magic + 8, kMagic) && std::getline(in, text) && text == header) {
          PrefilteredNdf p = PrefilteredNdf::read(in);
          p.settings = settings;
          return p;
        }
      } catch (const RuntimeFailure&) {
        // A damaged entry: rebuilt below.
      }
    }
  }
  PrefilteredNdf p = precompute_prefiltered_ndf(map, intrinsic_roughness, settings);
  if (!path.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (!ec) {
      try {
        AtomicFile file(path);
        {
          std::ofstream out(file.temp_path(), std::ios::binary);
          out.write(kMagic, 8);
          out << header << '\n';
          p.write(out);
          if (!out) throw RuntimeFailure("writing " + path.string());
        }
        file.commit();
      } catch (const RuntimeFailure&) {
        // An unwritable cache costs a precompute next time, nothing else.
      }
    }
  }
  return p;
}

}  // namespace glintlab
