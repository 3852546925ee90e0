#include "render/reference_cache.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <iostream>

#include "core/cache_directory.hpp"
#include "core/atomic_file.hpp"
#include "core/hash.hpp"
#include "core/image_io.hpp"

namespace glintlab {

ReferenceCache::ReferenceCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path ReferenceCache::default_directory() { return default_cache_directory(); }

std::uint64_t ReferenceCache::key(const Scene& scene, const Camera& camera, int width, int height,
                                  const ReferenceSettings& settings, const ReferenceBackend& backend,
                                  const std::string& renderer, bool progressive) {
  Hasher h;
  h.text(progressive ? "glintlab-reference-progressive-v2" : "glintlab-reference-v2");
  h.value(scene.content_hash());
  hash_camera(h, camera);
  h.value(width);
  h.value(height);
  if (!progressive) h.value(settings.spp);
  h.value(settings.subpixels());
  h.value(settings.effective_light_samples());
  h.value(settings.seed);
  h.text(settings.filter.text());
  h.text(backend.id());
  h.value(backend.estimator_hash());
  h.text(renderer);
  return h.digest();
}

std::filesystem::path ReferenceCache::path(std::uint64_t key, const char* extension) const {
  char name[40];
  std::snprintf(name, sizeof name, "ref-%016llx.%s", static_cast<unsigned long long>(key), extension);
  return directory_ / name;
}

std::optional<ReferenceFrame> ReferenceCache::load(std::uint64_t key) const {
  if (!enabled()) return std::nullopt;
  const auto exr = path(key, "exr"), meta = path(key, "json");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(meta, ec) || !std::filesystem::is_regular_file(exr, ec)) return std::nullopt;
  try {
    std::ifstream in(meta);
    const auto j = nlohmann::json::parse(in);
    ReferenceFrame r;
    r.passes = j.at("passes").get<int>();
    r.spp = j.at("spp").get<int>();
    r.pass_luminance = j.at("pass_luminance").get<std::vector<double>>();
    r.pass_luminance_specular = j.at("pass_luminance_specular").get<std::vector<double>>();
    r.mean = {read_exr(exr), read_exr(exr, "specular")};
    r.standard_error = read_exr(exr, "standard_error");
    r.even_passes = read_exr(exr, "even_passes");
    r.odd_passes = read_exr(exr, "odd_passes");
    if (r.passes < 1 || static_cast<int>(r.pass_luminance.size()) != r.passes) throw std::runtime_error("bad pass count");
    return r;
  } catch (const std::exception& e) {
    std::cerr << "glintlab: ignoring unreadable cache entry " << exr.string() << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

void ReferenceCache::store(std::uint64_t key, const ReferenceFrame& frame) const {
  if (!enabled()) return;
  try {
    write_exr(path(key, "exr"), {{"", &frame.mean.total},
                                 {"specular", &frame.mean.specular},
                                 {"standard_error", &frame.standard_error},
                                 {"even_passes", &frame.even_passes},
                                 {"odd_passes", &frame.odd_passes}});
    const nlohmann::json j = {{"passes", frame.passes},
                              {"spp", frame.spp},
                              {"pass_luminance", frame.pass_luminance},
                              {"pass_luminance_specular", frame.pass_luminance_specular}};
    write_text_file(path(key, "json"), j.dump() + "\n");
  } catch (const std::exception& e) {
    std::cerr << "glintlab: cannot write to the reference cache: " << e.what() << "\n";
  }
}

}  // namespace glintlab
