#pragma once
// The prefiltered NDF pyramids (deng2022) of a scene's normal-map-glints materials on the GPU: one
// pair of storage buffers per prefilter setting, made on first use (read from the cache or
// precomputed) and kept while the scene lives.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/objects.hpp"
#include "prefilter/prefiltered_ndf.hpp"
#include "scene/materials/material.hpp"

namespace glintlab {

class PrefilteredNdfs {
 public:
  PrefilteredNdfs(const std::vector<Material>& materials, std::filesystem::path cache_directory);

  /// Makes the pyramids of `settings` resident and binds them (kPrefilteredNdf*Binding).
  void bind(const PrefilterSettings& settings);
  /// The CPU pyramid of material m under `settings` (null if m has none); made on first use.
  const PrefilteredNdf* pyramid(int material, const PrefilterSettings& settings);

 private:
  struct Resident {
    std::vector<std::unique_ptr<PrefilteredNdf>> per_material;
    gl::Buffer records, values;
  };
  Resident& resident(const PrefilterSettings& settings);

  struct Source {
    std::shared_ptr<const NormalMap> map;
    double intrinsic_roughness = 0.0;
  };
  std::vector<Source> sources_;  ///< per material; map null where it has no pyramid
  std::filesystem::path cache_directory_;
  std::map<std::string, Resident> resident_;  ///< by PrefilterSettings::describe()
};


}  // namespace glintlab
