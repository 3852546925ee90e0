#include "eval/outputs.hpp"

#include <cstdio>

#include "core/colour.hpp"
#include "core/image_io.hpp"

namespace glintlab {

void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film) {
  write_exr(dir / (stem + ".exr"), {{"", &frame.total}, {"specular", &frame.specular}});
  write_png(dir / (stem + ".png"), tonemap_for_display(frame.total, film.exposure, film.bloom));
}

void write_reference(const std::filesystem::path& dir, const std::string& stem, const ReferenceFrame& reference,
                     const Film& film) {
  write_exr(dir / (stem + ".exr"), {{"", &reference.mean.total},
                                    {"specular", &reference.mean.specular},
                                    {"standard_error", &reference.standard_error}});
  write_png(dir / (stem + ".png"), tonemap_for_display(reference.mean.total, film.exposure, film.bloom));
}

nlohmann::json run_metadata(Session& session) {
  nlohmann::json json;
  json["scene"] = session.scene().source;
  json["width"] = session.width();
  json["height"] = session.height();
  json["device"] = session.context().info().renderer;
  json["reference_backend"] = session.reference_backend().id();
  return json;
}

std::string describe_reference(const ReferenceFrame& reference) {
  char line[200];
  std::snprintf(line, sizeof line, "reference %d spp (%d passes), noise rmse %.3g, energy +- %.2g%%", reference.spp,
                reference.passes, reference.noise_rmse(), 100.0 * reference.relative_energy_error());
  return line;
}

}  // namespace glintlab
