#pragma once
// `glintlab prefilter`: deng2022's pyramids of a scene's normal-map-glints materials, loaded from
// the cache or precomputed, reported level by level (footprints, kept blocks, compression error,
// time, storage) and, on request, measured against Yan 2016's NDF images of the same footprints.
#include <filesystem>
#include <string>

#include "prefilter/prefiltered_ndf.hpp"
#include "scene/scene.hpp"

namespace glintlab {

struct PrefilterReportOptions {
  PrefilterSettings settings;
  int accuracy_footprints = 0;  ///< per level, stored and in-between footprints compared with yan2016
  bool use_cache = true;
  std::filesystem::path json;   ///< also written here when set
};

/// Prints the report to stdout; throws InputError when the scene has no normal-map-glints material.
void run_prefilter_report(const Scene& scene, const PrefilterReportOptions& options);

}  // namespace glintlab
