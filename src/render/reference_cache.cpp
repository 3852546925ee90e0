#include "render/reference_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <iostream>

#include "core/cache_directory.hpp"
#include "core/cache_entry.hpp"
#include "core/file_access.hpp"
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
  h.text(progressive ? "glintlab-reference-progressive-v3" : "glintlab-reference-v3");
  h.value(scene.content_hash());
  hash_camera(h, camera);
  h.value(width);
  h.value(height);
  if (!progressive) h.value(settings.spp);
  h.value(settings.subpixels());
  h.value(settings.effective_light_samples());
  h.value(settings.seed);
  h.text(settings.filter.text());
  // A tile's key differs from its film's (the whole film's keys are as before tiles existed).
  if (const FilmRegion r = settings.region.within(width, height); r != FilmRegion{0, 0, width, height}) {
    h.text("region");
    for (int v : {r.x, r.y, r.width, r.height}) h.value(v);
  }
  if (settings.max_depth != 1) {
    h.text("max_depth");
    h.value(settings.max_depth);
  }
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

namespace {

std::uint64_t checksum_of(const std::string& bytes) {
  Hasher h;
  h.bytes(bytes.data(), bytes.size());
  return h.digest();
}

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

/// Why a frame read from an entry is not one of width x height with its passes, or empty.
std::string shape_problem(const ReferenceFrame& r, int width, int height) {
  for (const Image* image : {&r.mean.total, &r.mean.specular, &r.standard_error, &r.even_passes, &r.odd_passes}) {
    if (image->width() != width || image->height() != height)
      return "an image of " + std::to_string(image->width()) + "x" + std::to_string(image->height()) + ", not " +
             std::to_string(width) + "x" + std::to_string(height);
    if (image->count_non_finite() != 0) return "a pixel is NaN or infinite";
  }
  if (r.passes < 1 || r.spp < r.passes || static_cast<int>(r.pass_luminance.size()) != r.passes ||
      static_cast<int>(r.pass_luminance_specular.size()) != r.passes)
    return "its pass counts disagree";
  if (!all_finite(r.pass_luminance) || !all_finite(r.pass_luminance_specular)) return "a pass mean is not finite";
  return {};
}

}  // namespace

std::optional<ReferenceFrame> ReferenceCache::load(std::uint64_t key, int width, int height) const {
  if (!enabled()) return std::nullopt;
  const auto exr = path(key, "exr"), meta = path(key, "json");
  // The JSON is written last: without it (or without the EXR) there is no entry.
  if (file_kind(meta, false) == FileKind::missing || file_kind(exr, false) == FileKind::missing) return std::nullopt;
  std::string problem;
  try {
    const auto j = nlohmann::json::parse(read_regular_file(meta, "", kMaxTextFileBytes));
    if (j.at("exr_checksum").get<std::uint64_t>() != checksum_of(read_regular_file(exr, "", kMaxBinaryFileBytes)))
      throw std::runtime_error("the EXR's checksum is wrong");
    ReferenceFrame r;
    r.passes = j.at("passes").get<int>();
    r.spp = j.at("spp").get<int>();
    r.pass_luminance = j.at("pass_luminance").get<std::vector<double>>();
    r.pass_luminance_specular = j.at("pass_luminance_specular").get<std::vector<double>>();
    r.mean = {read_exr(exr), read_exr(exr, "specular")};
    r.standard_error = read_exr(exr, "standard_error");
    r.even_passes = read_exr(exr, "even_passes");
    r.odd_passes = read_exr(exr, "odd_passes");
    problem = shape_problem(r, width, height);
    if (problem.empty()) return r;
  } catch (const std::exception& e) {
    problem = e.what();
  }
  warn_rebuilding_cache_entry(exr, problem);
  return std::nullopt;
}

void ReferenceCache::store(std::uint64_t key, const ReferenceFrame& frame) const {
  if (!enabled()) return;
  try {
    for (const auto& p : {path(key, "exr"), path(key, "json")}) check_output_file(p, "");
    write_exr(path(key, "exr"), {{"", &frame.mean.total},
                                 {"specular", &frame.mean.specular},
                                 {"standard_error", &frame.standard_error},
                                 {"even_passes", &frame.even_passes},
                                 {"odd_passes", &frame.odd_passes}});
    const nlohmann::json j = {{"exr_checksum", checksum_of(read_regular_file(path(key, "exr"), "", kMaxBinaryFileBytes))},
                              {"passes", frame.passes},
                              {"spp", frame.spp},
                              {"pass_luminance", frame.pass_luminance},
                              {"pass_luminance_specular", frame.pass_luminance_specular}};
    write_text_file(path(key, "json"), j.dump() + "\n");
  } catch (const std::exception& e) {
    std::cerr << "glintlab: cannot write to the reference cache: " << e.what() << "\n";
  }
}

}  // namespace glintlab
