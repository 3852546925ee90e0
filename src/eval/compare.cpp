#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/image_io.hpp"
#include "eval/commands.hpp"
#include "eval/outputs.hpp"

namespace glintlab {

namespace {

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

/// Crops of the reference and each method side by side, enlarged, with 2-pixel gaps.
Image side_by_side(const std::vector<const Image*>& displays, const Region& r, int zoom) {
  const int cell = r.size * zoom, gap = 2;
  Image out(static_cast<int>(displays.size()) * (cell + gap) - gap, cell, glm::vec3(1.0f));
  for (std::size_t i = 0; i < displays.size(); ++i) {
    const Image crop = displays[i]->crop(r.x, r.y, r.size, r.size).upscale(zoom);
    for (int y = 0; y < crop.height(); ++y)
      for (int x = 0; x < crop.width(); ++x) out.at(static_cast<int>(i) * (cell + gap) + x, y) = crop.at(x, y);
  }
  return out;
}

std::string format_table(const std::vector<MethodMetrics>& rows) {
  std::ostringstream s;
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %10s %10s %8s %9s %9s %9s\n", "method", "rmse", "rmse_spec", "psnr",
                "energy", "e_spec", "max_err");
  s << line;
  for (const auto& r : rows) {
    const auto& m = r.metrics;
    std::snprintf(line, sizeof line, "%-22s %10.5f %10.5f %8.2f %9.4f %9.4f %9.3f\n", r.method.c_str(), m.rmse,
                  m.rmse_specular, m.psnr, m.energy_ratio, m.energy_ratio_specular, m.max_error);
    s << line;
  }
  return s.str();
}

}  // namespace

std::vector<MethodMetrics> run_compare(Session& session, const std::vector<MethodChoice>& methods,
                                       const std::filesystem::path& out, int frame) {
  // Render everything first: a NaN anywhere fails the command before any file is written.
  const Frame reference = session.reference(frame);
  std::vector<Frame> frames;
  for (const auto& m : methods) frames.push_back(session.render(m, frame));

  std::vector<MethodMetrics> rows;
  std::vector<Image> errors;
  Image error_sum(session.width(), session.height());
  float error_scale = 0.0f;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    rows.push_back({methods[i].method->id, measure(frames[i].total, frames[i].specular, reference.total, reference.specular)});
    errors.push_back(abs_error_map(frames[i].total, reference.total));
    std::vector<float> sorted;
    for (std::size_t p = 0; p < errors.back().pixel_count(); ++p) {
      error_sum.pixels()[p] += errors.back().pixels()[p];
      sorted.push_back(errors.back().pixels()[p].r);
    }
    // One colour scale for all maps (the largest 99.5th percentile) so they compare at a glance.
    auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(0.995 * static_cast<double>(sorted.size() - 1));
    std::nth_element(sorted.begin(), nth, sorted.end());
    error_scale = std::max(error_scale, *nth);
  }
  if (error_scale <= 0.0f) error_scale = 1.0f;

  const Film& film = session.scene().film;
  write_frame(out, "reference", reference, film);
  std::vector<Image> displays{tonemap_for_display(reference.total, film.exposure, film.bloom)};
  for (std::size_t i = 0; i < methods.size(); ++i) {
    write_frame(out, methods[i].method->id, frames[i], film);
    write_png(out / (methods[i].method->id + "-error.png"), false_colour(errors[i], error_scale));
    displays.push_back(tonemap_for_display(frames[i].total, film.exposure, film.bloom));
  }
  std::vector<const Image*> display_ptrs;
  for (const auto& d : displays) display_ptrs.push_back(&d);
  const auto regions = worst_regions(error_sum, std::max(16, std::min(session.width(), session.height()) / 8), 3);
  nlohmann::json crops = nlohmann::json::array();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const std::string name = "worst-region-" + std::to_string(r + 1) + ".png";
    write_png(out / name, side_by_side(display_ptrs, regions[r], std::max(1, 192 / regions[r].size)));
    crops.push_back({{"file", name}, {"x", regions[r].x}, {"y", regions[r].y}, {"size", regions[r].size}});
  }

  std::ostringstream csv;
  csv << "method,rmse,rmse_specular,psnr,energy_ratio,energy_ratio_specular,max_error\n";
  nlohmann::json json;
  json["scene"] = session.scene().source;
  json["frame"] = frame;
  json["width"] = session.width();
  json["height"] = session.height();
  json["reference_spp"] = session.reference_settings().spp;
  json["reference_light_samples"] = session.reference_settings().effective_light_samples();
  json["device"] = session.context().info().renderer;
  json["error_map_scale"] = error_scale;
  json["crops"] = crops;
  json["columns"] = "crops: reference, then methods in order";
  for (const auto& row : rows) {
    const auto& m = row.metrics;
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.8g,%.8g,%.6g,%.8g,%.8g,%.8g\n", row.method.c_str(), m.rmse, m.rmse_specular,
                  m.psnr, m.energy_ratio, m.energy_ratio_specular, m.max_error);
    csv << line;
    json["methods"].push_back({{"method", row.method},
                               {"rmse", m.rmse},
                               {"rmse_specular", m.rmse_specular},
                               {"psnr", m.psnr},
                               {"energy_ratio", m.energy_ratio},
                               {"energy_ratio_specular", m.energy_ratio_specular},
                               {"max_error", m.max_error}});
  }
  write_text_file(out / "metrics.csv", csv.str());
  write_text_file(out / "metrics.json", json.dump(2) + "\n");
  std::cout << "scene " << session.scene().source << ", " << session.width() << "x" << session.height()
            << ", reference " << session.reference_settings().spp << " spp\n"
            << format_table(rows) << "written to " << out.string() << "/\n";
  return rows;
}

}  // namespace glintlab
