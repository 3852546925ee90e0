#include "eval/outputs.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "core/colour.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/image_io.hpp"

namespace glintlab {

FrameOutput frame_output(const std::string& path, const std::string& default_stem) {
  const std::filesystem::path p(path);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!ext.empty() && ext != ".exr" && ext != ".png")
    throw InputError("-o " + path + ": glintlab cannot write '" + p.extension().string() +
                     "' files; allowed: NAME.exr or NAME.png (both are written), or a directory without an extension");
  const bool file = !ext.empty();
  FrameOutput out{file ? p.parent_path() : p, file ? p.stem().string() : default_stem};
  check_output_directory(out.dir);
  for (const char* e : {".exr", ".png"}) check_output_file(out.dir / (out.stem + e), "-o");
  return out;
}

void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film) {
  write_exr(dir / (stem + ".exr"), {{"", &frame.total}, {"specular", &frame.specular}});
  write_png(dir / (stem + ".png"), tonemap_for_display(frame.total, film.exposure, film.bloom));
}

void write_reference(const std::filesystem::path& dir, const std::string& stem, const ReferenceFrame& reference,
                     const Film& film) {
  // The passes' standard error, and the stated error (+-2 of it: about 95% of references hold the
  // truth; docs/methods.md, "Ground truth"). With one pass neither is known: both are 0.
  const Image stated = reference.passes >= 2 ? reference.stated_error() : reference.standard_error;
  write_exr(dir / (stem + ".exr"), {{"", &reference.mean.total},
                                    {"specular", &reference.mean.specular},
                                    {"standard_error", &reference.standard_error},
                                    {"stated_error", &stated}});
  write_png(dir / (stem + ".png"), tonemap_for_display(reference.mean.total, film.exposure, film.bloom));
}

nlohmann::json run_metadata(Session& session) {
  nlohmann::json json;
  json["scene"] = session.scene().source;
  json["width"] = session.width();
  json["height"] = session.height();
  json["device"] = session.context().info().renderer;
  json["reference_backend"] = session.reference_backend().id();
  json["reference_filter"] = session.reference_settings().filter.text();
  json["reference_max_depth"] = session.reference_settings().max_depth;
  return json;
}

MetricsViewing metrics_viewing(const Session& session) {
  MetricsViewing viewing;
  viewing.display_exposure = session.scene().film.exposure;
  if (session.options().pixels_per_degree > 0) viewing.pixels_per_degree = session.options().pixels_per_degree;
  return viewing;
}

std::string describe_reference(const ReferenceFrame& reference) {
  char line[200];
  std::snprintf(line, sizeof line, "reference %d spp (%d passes), noise rmse %.3g, energy +- %.2g%%", reference.spp,
                reference.passes, reference.noise_rmse(), 100.0 * reference.relative_energy_error());
  return line;
}

// At half the samples, so above what the full reference shows against the truth.
ImageMetrics half_reference_floor(const ReferenceFrame& reference, const MetricsViewing& viewing) {
  ImageMetrics floor;
  if (reference.passes < 2) return floor;
  const MetricsReference odd(reference.odd_passes, reference.odd_passes, viewing);
  floor.flip_ldr = flip::mean(odd.flip_ldr_map(reference.even_passes));
  floor.flip_hdr = flip::mean(odd.flip_hdr_map(reference.even_passes));
  floor.sparkle_distance = sparkle_distance(reference.even_passes, reference.odd_passes, kSparkleBlock);
  return floor;
}

}  // namespace glintlab
