#include "eval/metrics_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/colour.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"

namespace glintlab {

namespace {

enum class ImageKind { radiance, display };

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

ImageKind kind_of(const std::string& path, const char* role) {
  const std::string ext = lower_extension(path);
  if (ext == ".exr") return ImageKind::radiance;
  if (ext == ".png") return ImageKind::display;
  throw InputError(std::string(role) + " " + path + ": extension '" + ext + "' (allowed: .exr for radiance, .png for a display-encoded sRGB picture)");
}

// A PNG's sRGB values as the linear light the display emits.
Image decode_srgb(const Image& encoded) {
  Image out(encoded.width(), encoded.height());
  for (std::size_t i = 0; i < encoded.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) out.pixels()[i][c] = srgb_decode(encoded.pixels()[i][c]);
  return out;
}

Image read_image(const std::string& path, ImageKind kind) {
  return kind == ImageKind::radiance ? read_exr(path) : decode_srgb(read_ldr_image(path));
}

void require_finite(const Image& image, const std::string& path) {
  for (std::size_t i = 0; i < image.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(image.pixels()[i][c]))
        throw InputError(path + ": pixel (" + std::to_string(i % image.width()) + ", " +
                         std::to_string(i / image.width()) + ") is " + std::to_string(image.pixels()[i][c]) +
                         " (allowed: finite values)");
}

Image as_image(const std::vector<float>& map, int width, int height) {
  Image out(width, height);
  for (std::size_t i = 0; i < map.size(); ++i) out.pixels()[i] = glm::vec3(map[i]);
  return out;
}

}  // namespace

flip::Exposures parse_hdr_exposures(const std::string& text) {
  flip::Exposures e;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%d%c", &e.start, &e.stop, &e.count, &tail) != 3 || !std::isfinite(e.start) ||
      !std::isfinite(e.stop) || e.start > e.stop || e.count < 2 || e.count > 64)
    throw InputError("--hdr-exposures '" + text + "': allowed: START,STOP,COUNT with START <= STOP and 2 <= COUNT <= 64");
  return e;
}

void run_metrics_command(const MetricsCommandOptions& o) {
  const ImageKind kind = kind_of(o.test, "test");
  if (kind_of(o.reference, "reference") != kind)
    throw InputError("test " + o.test + " and reference " + o.reference + " are of different kinds (allowed: both .exr or both .png)");
  if (kind == ImageKind::display && o.hdr_exposures)
    throw InputError("--hdr-exposures: HDR-FLIP needs radiance (.exr), not the .png pictures given");
  if (!o.flip_map.empty()) {
    if (lower_extension(o.flip_map) != ".png") throw InputError("--flip-map " + o.flip_map + ": allowed: a .png file name");
    check_output_file(o.flip_map, "--flip-map");
  }
  if (!o.json.empty()) {
    if (lower_extension(o.json) != ".json") throw InputError("-o " + o.json + ": allowed: a .json file name");
    check_output_file(o.json, "-o");
  }
  const Image test = read_image(o.test, kind), reference = read_image(o.reference, kind);
  require_finite(test, o.test);
  require_finite(reference, o.reference);
  if (test.width() != reference.width() || test.height() != reference.height())
    throw InputError("test " + o.test + " is " + std::to_string(test.width()) + "x" + std::to_string(test.height()) +
                     ", reference " + o.reference + " " + std::to_string(reference.width()) + "x" +
                     std::to_string(reference.height()) + " (allowed: the same size)");
  const double ppd = o.pixels_per_degree > 0 ? o.pixels_per_degree : flip::default_pixels_per_degree();

  nlohmann::json json{{"test", o.test}, {"reference", o.reference}, {"width", test.width()},
                      {"height", test.height()}, {"pixels_per_degree", ppd}};
  json["rmse"] = rmse(test, reference);
  json["energy_ratio"] = energy_ratio(test, reference);
  json["sparkle_distance"] = sparkle_distance(test, reference, kSparkleBlock);
  std::vector<float> map;
  if (kind == ImageKind::display) {
    // The pictures are what the display shows: LDR-FLIP on their linear values.
    map = flip::ldr_error_map(test, reference, ppd);
    json["flip_ldr"] = flip::mean(map);
  } else {
    json["flip_ldr"] = flip::mean(flip::ldr_error_map(displayed_linear(test, o.display_exposure),
                                                      displayed_linear(reference, o.display_exposure), ppd));
    json["display_exposure"] = o.display_exposure;
    const flip::Exposures exposures = o.hdr_exposures ? *o.hdr_exposures : flip::automatic_exposures(reference);
    map = flip::HdrReference(reference, ppd, exposures).error_map(test);
    json["flip_hdr"] = flip::mean(map);
    json["hdr_exposures"] = {{"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
  }
  if (!o.flip_map.empty()) write_png(o.flip_map, false_colour(as_image(map, test.width(), test.height()), 1.0f));
  if (!o.json.empty()) write_text_file(o.json, json.dump(2) + "\n");
  std::printf("rmse              %.6g\nenergy_ratio      %.6g\nsparkle_distance  %.6g\nflip_ldr          %.6f\n",
              json["rmse"].get<double>(), json["energy_ratio"].get<double>(), json["sparkle_distance"].get<double>(),
              json["flip_ldr"].get<double>());
  if (json.contains("flip_hdr"))
    std::printf("flip_hdr          %.6f  (exposures %.4f .. %.4f, %d)\n", json["flip_hdr"].get<double>(),
                json["hdr_exposures"]["start"].get<double>(), json["hdr_exposures"]["stop"].get<double>(),
                json["hdr_exposures"]["count"].get<int>());
  std::printf("pixels_per_degree %.4f\n", ppd);
}

}  // namespace glintlab
