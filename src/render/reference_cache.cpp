#include "render/reference_cache.hpp"

#include <cstdio>
#include <iostream>

#include "core/cache_directory.hpp"
#include "core/hash.hpp"
#include "core/image_io.hpp"

namespace glintlab {

ReferenceCache::ReferenceCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path ReferenceCache::default_directory() { return default_cache_directory(); }

std::uint64_t ReferenceCache::key(const Scene& scene, const Camera& camera, int width, int height,
                                  const ReferenceSettings& settings, std::uint64_t shaders_hash,
                                  const std::string& renderer) {
  Hasher h;
  h.text("glintlab-reference-v1");
  h.value(scene.content_hash());
  hash_camera(h, camera);
  h.value(width);
  h.value(height);
  h.value(settings.spp);
  h.value(settings.effective_light_samples());
  h.value(settings.seed);
  h.value(shaders_hash);
  h.text(renderer);
  return h.digest();
}

std::filesystem::path ReferenceCache::path(std::uint64_t key) const {
  char name[32];
  std::snprintf(name, sizeof name, "ref-%016llx.exr", static_cast<unsigned long long>(key));
  return directory_ / name;
}

std::optional<Frame> ReferenceCache::load(std::uint64_t key) const {
  if (!enabled()) return std::nullopt;
  const auto p = path(key);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
  try {
    return Frame{read_exr(p), read_exr(p, "specular")};
  } catch (const std::exception& e) {
    std::cerr << "glintlab: ignoring unreadable cache entry " << p.string() << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

void ReferenceCache::store(std::uint64_t key, const Frame& frame) const {
  if (!enabled()) return;
  try {
    write_exr(path(key), {{"", &frame.total}, {"specular", &frame.specular}});
  } catch (const std::exception& e) {
    std::cerr << "glintlab: cannot write to the reference cache: " << e.what() << "\n";
  }
}

}  // namespace glintlab
