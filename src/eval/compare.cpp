#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/image_io.hpp"
#include "core/label_font.hpp"
#include "core/output_stage.hpp"
#include "eval/commands.hpp"
#include "eval/crop_strip.hpp"
#include "eval/outputs.hpp"

namespace glintlab {

namespace {

/// A CSV field: quoted when it holds a comma (a variant's name, "podee{area=lens,glossy=off}").
std::string csv_field(const std::string& text) {
  return text.find(',') == std::string::npos ? text : "\"" + text + "\"";
}

/// A per-pixel map as an image (the value in every channel), for false_colour.
Image as_image(const std::vector<float>& map, int width) {
  Image out(width, width > 0 ? static_cast<int>(map.size()) / width : 0);
  for (std::size_t i = 0; i < map.size(); ++i) out.pixels()[i] = glm::vec3(map[i]);
  return out;
}

struct Region {
  int x, y, size;
  double error;
};

/// The `count` non-overlapping square windows with the largest summed error (summed over methods).
std::vector<Region> worst_regions(const Image& error_sum, int size, int count) {
  size = std::max(4, std::min({size, error_sum.width(), error_sum.height()}));
  // Summed-area table for O(1) window sums.
  const int w = error_sum.width(), h = error_sum.height();
  std::vector<double> sat(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);
  auto at = [&](int x, int y) -> double& { return sat[static_cast<std::size_t>(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) at(x + 1, y + 1) = error_sum.at(x, y).r + at(x, y + 1) + at(x + 1, y) - at(x, y);
  std::vector<Region> chosen;
  const int step = std::max(1, size / 4);
  for (int n = 0; n < count; ++n) {
    Region best{0, 0, size, -1.0};
    for (int y = 0; y + size <= h; y += step)
      for (int x = 0; x + size <= w; x += step) {
        bool overlaps = false;
        for (const auto& c : chosen)
          overlaps |= x < c.x + c.size && c.x < x + size && y < c.y + c.size && c.y < y + size;
        if (overlaps) continue;
        const double e = at(x + size, y + size) - at(x, y + size) - at(x + size, y) + at(x, y);
        if (e > best.error) best = {x, y, size, e};
      }
    if (best.error <= 0.0) break;
    chosen.push_back(best);
  }
  return chosen;
}

std::string format_table(const std::vector<MethodMetrics>& rows, const ReferenceFrame& reference,
                         const ImageMetrics& floor) {
  std::ostringstream s;
  // The name column: 22 wide, wider for a longer name (a variant's).
  int width = 22;
  for (const auto& r : rows) width = std::max(width, static_cast<int>(r.method.size()));
  char line[512];
  std::snprintf(line, sizeof line, "%-*s %10s %10s %8s %9s %9s %9s %8s %8s %8s\n", width, "method", "rmse",
                "rmse_spec", "psnr", "energy", "e_spec", "max_err", "flip", "hdr_flip", "sparkle");
  s << line;
  for (const auto& r : rows) {
    const auto& m = r.metrics;
    std::snprintf(line, sizeof line, "%-*s %10.5f %10.5f %8.2f %9.4f %9.4f %9.3f %8.4f %8.4f %8.4f\n", width,
                  r.method.c_str(), m.rmse, m.rmse_specular, m.psnr, m.energy_ratio, m.energy_ratio_specular,
                  m.max_error, m.flip_ldr, m.flip_hdr, m.sparkle_distance);
    s << line;
  }
  std::snprintf(line, sizeof line, "%-*s %10.5f %10s %8s  +-%.4f  +-%.4f %9s %8.4f %8.4f %8.4f\n", width,
                "(reference noise)", reference.noise_rmse(), "", "", reference.relative_energy_error(),
                reference.relative_energy_error(true), "", floor.flip_ldr, floor.flip_hdr, floor.sparkle_distance);
  s << line;
  return s.str();
}

}  // namespace

std::vector<MethodMetrics> run_compare(Session& session, const std::vector<MethodChoice>& methods,
                                       const std::filesystem::path& out, int frame) {
  // Render everything first: a NaN anywhere fails the command before any file is written.
  const Session::Rendered all = session.render_with_reference(methods, frame);
  const std::vector<Frame>& frames = all.methods;
  const ReferenceFrame& reference_estimate = all.reference;
  const Frame& reference = reference_estimate.mean;
  const double noise = reference_estimate.noise_rmse();
  const double energy_error = reference_estimate.relative_energy_error();
  const double energy_error_specular = reference_estimate.relative_energy_error(true);

  // One method's images at a time (a film of many methods is several GiB): each error map is
  // made for its metrics and the error sum, then dropped and made again when written.
  std::vector<MethodMetrics> rows;
  const MetricsViewing viewing = metrics_viewing(session);
  const MetricsReference metrics_reference(reference.total, reference.specular, viewing);
  const ImageMetrics floor = half_reference_floor(reference_estimate, viewing);
  // Published as a unit: written into a staging folder, moved into `out` with the metrics last.
  OutputStage stage(out);
  const std::filesystem::path& staged = stage.path();
  Image error_sum(session.width(), session.height());
  float error_scale = 0.0f;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    std::vector<float> flip_map;  // written now: made once, for the mean and the picture
    rows.push_back({methods[i].display_name(),
                    metrics_reference.measure(frames[i].total, frames[i].specular, &flip_map)});
    write_png(staged / (methods[i].file_stem() + "-flip.png"), false_colour(as_image(flip_map, session.width()), 1.0f));
    const Image error = abs_error_map(frames[i].total, reference.total);
    for (std::size_t p = 0; p < error.pixel_count(); ++p) error_sum.pixels()[p] += error.pixels()[p];
    // One colour scale for all maps (the largest 99.5th percentile) so they compare at a glance.
    error_scale = std::max(error_scale, error_percentile(error, kErrorMapPercentile));
  }
  if (error_scale <= 0.0f) error_scale = 1.0f;
  const auto regions = worst_regions(error_sum, std::max(16, std::min(session.width(), session.height()) / 8), 3);
  const int columns = static_cast<int>(methods.size()) + 1;
  std::string font_error;
  const std::optional<LabelFont> font = LabelFont::load(kLabelFontFile, font_error);
  if (!font)
    std::cerr << "glintlab: warning: " << font_error
              << ": the worst-region crops are written without their names (Debian: apt-get install "
                 "fonts-dejavu-core)\n";
  std::vector<CropStrip> strips;
  for (const auto& r : regions)
    strips.emplace_back(columns, CropWindow{r.x, r.y, r.size}, std::max(1, 192 / r.size), font.has_value());
  auto add_crops = [&](int column, const std::string& name, const Image& display) {
    for (auto& strip : strips) {
      strip.paste(column, display);
      if (font) strip.label(column, name, *font);
    }
  };

  const Film& film = session.scene().film;
  write_reference(staged, "reference", reference_estimate, film);
  add_crops(0, "reference", tonemap_for_display(reference.total, film.exposure, film.bloom));
  for (std::size_t i = 0; i < methods.size(); ++i) {
    write_frame(staged, methods[i].file_stem(), frames[i], film);
    write_png(staged / (methods[i].file_stem() + "-error.png"),
              false_colour(abs_error_map(frames[i].total, reference.total), error_scale));
    add_crops(static_cast<int>(i) + 1, methods[i].display_name(),
              tonemap_for_display(frames[i].total, film.exposure, film.bloom));
  }
  nlohmann::json crops = nlohmann::json::array();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const std::string name = "worst-region-" + std::to_string(r + 1) + ".png";
    write_png(staged / name, strips[r].image());
    // zoom, cell (its side in the strip), gap and the label band below the crops: what `glintlab
    // report` needs to cut the crops out again.
    crops.push_back({{"file", name},
                     {"x", regions[r].x},
                     {"y", regions[r].y},
                     {"size", regions[r].size},
                     {"zoom", strips[r].zoom()},
                     {"cell", strips[r].cell()},
                     {"gap", CropStrip::kGap},
                     {"label_height", strips[r].label_height()}});
  }

  std::ostringstream csv;
  // The reference's own error beside every number it judges: its noise RMSE (a method's RMSE
  // cannot be told from another's closer than this) and the stated error of each energy ratio (its
  // standard error widened for few passes: within 2 of it for about 95% of references).
  // block_rmse and glint_detail hold against a reference that is an independent realisation of a
  // glinty surface (core/metrics.hpp), where the per-pixel RMSE rewards blur.
  // flip_ldr, flip_hdr (perceived difference, 0 .. 1) and sparkle_distance (the glints' number,
  // size and brightness per 16 x 16 tile) beside them (core/metrics.hpp, core/flip.hpp).
  csv << "method,rmse,rmse_specular,psnr,energy_ratio,energy_ratio_specular,max_error,reference_noise_rmse,"
         "energy_ratio_error,energy_ratio_specular_error,block_rmse,glint_detail,flip_ldr,flip_hdr,sparkle_distance\n";
  nlohmann::json json = run_metadata(session);
  json["frame"] = frame;
  json["statistics_block"] = kStatisticsBlock;
  json["sparkle_block"] = kSparkleBlock;
  json["flip_pixels_per_degree"] = viewing.pixels_per_degree;
  json["flip_display_exposure"] = viewing.display_exposure;
  const flip::Exposures& exposures = metrics_reference.hdr_exposures();
  json["flip_hdr_exposures"] = {{"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
  // Two half-references against each other: method differences below these are the reference's noise.
  json["reference_floor"] = {{"flip_ldr", floor.flip_ldr},
                             {"flip_hdr", floor.flip_hdr},
                             {"sparkle_distance", floor.sparkle_distance},
                             {"definition", "the reference's even passes against its odd passes (each half its samples)"}};
  // The truth's glint detail: the reference's, its noise taken out.
  json["reference_glint_detail"] = glint_detail(reference.total, &reference_estimate.standard_error);
  json["reference_spp"] = reference_estimate.spp;
  json["reference_passes"] = reference_estimate.passes;
  json["reference_auto"] = session.options().spp_auto;
  json["reference_light_samples"] = session.reference_settings().effective_light_samples();
  json["reference_noise_rmse"] = noise;
  json["reference_energy_error"] = energy_error;
  json["reference_interval_scale"] = reference_estimate.interval_scale();
  json["reference_mean_luminance"] = luminance(glm::vec3(reference.total.mean()));
  if (session.options().spp_auto) {
    std::vector<const Frame*> ranked;
    for (const auto& f : frames) ranked.push_back(&f);
    json["reference_noise_target"] = reference_noise_target(reference, ranked, session.options().noise_fraction);
    json["reference_max_spp"] = session.options().max_spp;
  }
  json["error_map_scale"] = error_scale;
  json["crops"] = crops;
  json["columns"] = "crops: reference, then methods in order, each named in the band below it";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MethodMetrics& row = rows[i];
    const auto& m = row.metrics;
    char line[512];
    std::snprintf(line, sizeof line, "%s,%.8g,%.8g,%.6g,%.8g,%.8g,%.8g,%.6g,%.6g,%.6g,%.8g,%.6g,%.6g,%.6g,%.6g\n",
                  csv_field(row.method).c_str(), m.rmse, m.rmse_specular, m.psnr, m.energy_ratio,
                  m.energy_ratio_specular, m.max_error, noise, m.energy_ratio * energy_error,
                  m.energy_ratio_specular * energy_error_specular, m.block_rmse, m.glint_detail, m.flip_ldr,
                  m.flip_hdr, m.sparkle_distance);
    csv << line;
    json["methods"].push_back({{"method", row.method},
                               {"file", methods[i].file_stem()},  // <file>.png, <file>-error.png
                               {"rmse", m.rmse},
                               {"rmse_specular", m.rmse_specular},
                               {"psnr", m.psnr},
                               {"energy_ratio", m.energy_ratio},
                               {"energy_ratio_specular", m.energy_ratio_specular},
                               {"max_error", m.max_error},
                               {"reference_noise_rmse", noise},
                               {"energy_ratio_error", m.energy_ratio * energy_error},
                               {"energy_ratio_specular_error", m.energy_ratio_specular * energy_error_specular},
                               {"block_rmse", m.block_rmse},
                               {"glint_detail", m.glint_detail},
                               {"flip_ldr", m.flip_ldr},
                               {"flip_hdr", m.flip_hdr},
                               {"sparkle_distance", m.sparkle_distance}});
  }
  write_text_file(staged / "metrics.csv", csv.str());
  write_text_file(staged / "metrics.json", json.dump(2) + "\n");
  stage.publish({"metrics.csv", "metrics.json"});
  std::cout << "scene " << session.scene().source << ", " << session.width() << "x" << session.height() << ", "
            << describe_reference(reference_estimate) << "\n"
            << format_table(rows, reference_estimate, floor) << "written to " << out.string() << "/\n";
  return rows;
}

}  // namespace glintlab
