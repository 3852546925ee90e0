#pragma once
// On-disk cache of ground-truth frames, keyed by a hash of everything that affects them: scene
// content, camera, film size, reference settings, the backend (its id and its estimator's code)
// and the GL renderer.
// Location: default_cache_directory() (core/cache_directory.hpp).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "render/reference_backend.hpp"
#include "scene/scene.hpp"

namespace glintlab {

class ReferenceCache {
 public:
  /// An empty directory disables the cache.
  explicit ReferenceCache(std::filesystem::path directory);
  static std::filesystem::path default_directory();

  /// `progressive`: a key for a reference that grows pass by pass (--spp auto), without the spp.
  [[nodiscard]] static std::uint64_t key(const Scene& scene, const Camera& camera, int width, int height,
                                         const ReferenceSettings& settings, const ReferenceBackend& backend,
                                         const std::string& renderer, bool progressive = false);
  /// An entry is an EXR (mean, specular, standard error, even and odd passes) and a JSON of its
  /// passes and the EXR's checksum, written last so that a half-written entry is never read. An
  /// entry that is damaged (checksum), foreign (not width x height, pass counts that disagree) or
  /// holds a non-finite value is reported on stderr and not used: the caller renders it again.
  [[nodiscard]] std::optional<ReferenceFrame> load(std::uint64_t key, int width, int height) const;
  /// Failures to write are reported on stderr and otherwise ignored: the cache is an optimisation.
  void store(std::uint64_t key, const ReferenceFrame& frame) const;
  [[nodiscard]] bool enabled() const { return !directory_.empty(); }

 private:
  [[nodiscard]] std::filesystem::path path(std::uint64_t key, const char* extension) const;
  std::filesystem::path directory_;
};

}  // namespace glintlab
