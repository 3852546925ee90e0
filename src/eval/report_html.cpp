#include "eval/report_html.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include "core/colour.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "eval/report_svg.hpp"

namespace glintlab {

// Generated from src/eval/report/ (glintlab_embed_files in src/eval/CMakeLists.txt).
const std::map<std::string, std::string_view>& report_template_files();

namespace {

using nlohmann::json;

/// A table column, `digits` significant digits shown: which way is better ("lower", "higher" or
/// "one": closest to 1), and what differences in it the page may call a ranking: more than twice
/// `noise`, or for a column with per-row standard errors (`error_key`), more than twice those of
/// the two rows combined.
json column(const std::string& key, const std::string& label, const std::string& better, int digits) {
  return {{"key", key}, {"label", label}, {"better", better}, {"digits", digits}};
}

json with_noise(json c, double noise, const std::string& noise_label) {
  c["noise"] = noise;
  c["noise_label"] = noise_label;
  return c;
}

json with_error(json c, const std::string& error_key) {
  c["error_key"] = error_key;
  return c;
}

/// The colours of compare's error maps from 0 to their scale, as a CSS gradient: false_colour
/// itself evaluated at even steps, so the legend is the ramp the maps were painted with.
std::string error_ramp_css() {
  constexpr int steps = 17;
  Image values(steps, 1);
  for (int i = 0; i < steps; ++i) values.at(i, 0) = glm::vec3(static_cast<float>(i) / (steps - 1));
  const Image colours = false_colour(values, 1.0f);
  std::string css = "linear-gradient(to right";
  for (int i = 0; i < steps; ++i) {
    const glm::vec3 c = colours.at(i, 0);
    char stop[64];
    std::snprintf(stop, sizeof stop, ", rgb(%d,%d,%d) %.2f%%", unorm8(c.r), unorm8(c.g), unorm8(c.b),
                  100.0 * i / (steps - 1));
    css += stop;
  }
  return css + ")";
}

json compare_data(const CompareRun& c, const std::string& assets) {
  const double noise = c.reference_noise_rmse;
  const std::string noise_label = "the reference's noise RMSE";
  json table = {
      {"sort", "rmse"},
      {"columns",
       {column("method", "method", "", 0), with_noise(column("rmse", "RMSE", "lower", 4), noise, noise_label),
        with_noise(column("rmse_specular", "RMSE specular", "lower", 4), noise, noise_label),
        column("psnr", "PSNR (dB)", "higher", 3),
        with_error(column("energy_ratio", "energy ratio", "one", 4), "energy_ratio_error"),
        with_error(column("energy_ratio_specular", "energy ratio specular", "one", 4), "energy_ratio_specular_error"),
        column("max_error", "max error", "lower", 4)}},
      {"floors", {{{"label", "(reference noise)"}, {"values", {{"rmse", noise}, {"rmse_specular", noise}}}}}}};
  if (c.perceptual) {
    // Beside RMSE: what a viewer sees (FLIP) and whether the glints are right (sparkle distance),
    // each with what two half-references score against each other.
    const std::string floor_label = "two half-references against each other";
    table["columns"].push_back(with_noise(column("flip_ldr", "FLIP", "lower", 4), c.floor_flip_ldr, floor_label));
    table["columns"].push_back(with_noise(column("flip_hdr", "HDR-FLIP", "lower", 4), c.floor_flip_hdr, floor_label));
    table["columns"].push_back(
        with_noise(column("sparkle_distance", "sparkle distance", "lower", 4), c.floor_sparkle_distance, floor_label));
    table["floors"].push_back({{"label", "(half-references)"},
                               {"values",
                                {{"flip_ldr", c.floor_flip_ldr},
                                 {"flip_hdr", c.floor_flip_hdr},
                                 {"sparkle_distance", c.floor_sparkle_distance}}}});
  }
  json images = {{"reference", assets + "/reference.png"}, {"methods", json::array()}};
  json columns = {"reference"};
  for (const auto& r : c.rows) {
    json row = {{"method", r.method},
                {"rmse", r.rmse},
                {"rmse_specular", r.rmse_specular},
                {"psnr", r.psnr},
                {"energy_ratio", r.energy_ratio},
                {"energy_ratio_error", r.energy_ratio_error},
                {"energy_ratio_specular", r.energy_ratio_specular},
                {"energy_ratio_specular_error", r.energy_ratio_specular_error},
                {"max_error", r.max_error}};
    if (c.perceptual) {
      row["flip_ldr"] = r.flip_ldr;
      row["flip_hdr"] = r.flip_hdr;
      row["sparkle_distance"] = r.sparkle_distance;
    }
    table["rows"].push_back(row);
    json method_images = {{"method", r.method},
                          {"image", assets + "/" + r.file + ".png"},
                          {"error", assets + "/" + r.file + "-error.png"}};
    if (c.perceptual) method_images["flip"] = assets + "/" + r.file + "-flip.png";
    images["methods"].push_back(method_images);
    columns.push_back(r.method);
  }
  json regions = json::array();
  for (const auto& w : c.regions)
    regions.push_back(
        {{"strip", assets + "/" + w.file}, {"x", w.x}, {"y", w.y}, {"size", w.size}, {"cell", w.cell}, {"gap", w.gap}});
  return {{"table", table},
          {"images", images},
          {"regions", regions},
          {"columns", columns},
          {"error_map_scale", c.error_map_scale},
          {"error_ramp", error_ramp_css()}};
}

json animate_data(const AnimateRun& a, const std::string& assets) {
  json table = {{"sort", "mean_rmse"},
                {"columns",
                 {column("method", "method", "", 0),
                  with_noise(column("mean_rmse", "mean RMSE", "lower", 4), a.reference_noise_rmse,
                             "the reference's noise RMSE (mean over frames)"),
                  with_noise(column("flicker", "flicker", "lower", 4), a.flicker_floor, "the flicker floor")}},
                {"floors",
                 {{{"label", "(reference floor)"},
                   {"values", {{"mean_rmse", a.reference_noise_rmse}, {"flicker", a.flicker_floor}}}}}}};
  if (a.perceptual)
    for (const auto& [key, label] : {std::pair{"mean_flip_ldr", "mean FLIP"}, std::pair{"mean_flip_hdr", "mean HDR-FLIP"},
                                     std::pair{"mean_sparkle_distance", "mean sparkle distance"}})
      table["columns"].push_back(column(key, label, "lower", 4));
  std::vector<PlotSeries> series, flicker_series;
  std::vector<PlotBar> flicker;
  bool flicker_of_each_frame = true;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    const auto& r = a.rows[i];
    json row = {{"method", r.method}, {"mean_rmse", r.mean_rmse}, {"flicker", r.flicker}};
    if (a.perceptual) {
      row["mean_flip_ldr"] = r.mean_flip_ldr;
      row["mean_flip_hdr"] = r.mean_flip_hdr;
      row["mean_sparkle_distance"] = r.mean_sparkle_distance;
    }
    table["rows"].push_back(row);
    series.push_back({r.method, r.rmse_per_frame});
    flicker.push_back({r.method, r.flicker, "", false, i});
    // Frame 0 has no flicker: it is the first difference's end that is plotted.
    std::vector<double> values{std::numeric_limits<double>::quiet_NaN()};
    values.insert(values.end(), r.flicker_per_frame.begin(), r.flicker_per_frame.end());
    flicker_series.push_back({r.method, values});
    flicker_of_each_frame &= r.flicker_per_frame.size() + 1 == static_cast<std::size_t>(a.frames);
  }
  json videos = json::array();
  for (const auto& v : a.videos) videos.push_back({{"name", v.name}, {"src", assets + "/" + v.file + ".mp4"}});
  json plots = {line_plot_svg("RMSE of each frame against the reference", "RMSE", series,
                              {{"reference noise RMSE", a.reference_noise_rmse}})};
  // Outputs of animate before it wrote each frame's flicker have the mean alone.
  if (flicker_of_each_frame && a.frames > 1)
    plots.push_back(line_plot_svg("Flicker of each frame (its error's change from the frame before)", "flicker",
                                  flicker_series, {{"flicker floor (mean)", a.flicker_floor}}));
  plots.push_back(bar_chart_svg("Flicker over the frames", "", flicker, {{"flicker floor", a.flicker_floor}}));
  return {{"table", table}, {"videos", videos}, {"plots", plots}, {"frames", a.frames}};
}

json bench_data(const BenchRun& b) {
  // Ratios to conventional, the method every paper measures against; to the first row without it.
  const BenchRow* base = &b.rows.front();
  for (const auto& r : b.rows)
    if (r.method == "conventional") base = &r;
  const std::string base_name = base->method;
  auto ratio = [](double ms, double base_ms) { return base_ms > 0 ? ms / base_ms : 0.0; };
  json table = {{"sort", "wall_ms"},
                {"base", base_name},
                {"columns",
                 {column("method", "method", "", 0), column("wall_ms", "wall ms", "lower", 4),
                  column("wall_ratio", "wall / " + base_name, "lower", 3), column("gpu_ms", "GPU ms", "lower", 4),
                  column("gpu_ratio", "GPU / " + base_name, "lower", 3)}},
                {"floors", json::array()}};
  std::vector<PlotBar> wall, gpu;
  char note[64];
  for (std::size_t i = 0; i < b.rows.size(); ++i) {
    const auto& r = b.rows[i];
    const bool method = r.method.empty() || r.method[0] != '(';  // "(unshaded)": the floor, not a method
    const double wall_ratio = ratio(r.wall_ms, base->wall_ms), gpu_ratio = ratio(r.gpu_ms, base->gpu_ms);
    table["rows"].push_back({{"method", r.method},
                             {"wall_ms", r.wall_ms},
                             {"wall_ratio", wall_ratio},
                             {"gpu_ms", r.gpu_ms},
                             {"gpu_ratio", gpu_ratio},
                             {"muted", !method}});
    std::snprintf(note, sizeof note, "x%.2f of %s", wall_ratio, base_name.c_str());
    wall.push_back({r.method, r.wall_ms, note, !method, i});
    std::snprintf(note, sizeof note, "x%.2f of %s", gpu_ratio, base_name.c_str());
    gpu.push_back({r.method, r.gpu_ms, note, !method, i});
  }
  json plots = {bar_chart_svg("Wall time per frame (draw + glFinish, median)", "ms", wall, {}),
                bar_chart_svg("GPU time per frame (GL_TIME_ELAPSED, median)", "ms", gpu, {})};
  return {{"table", table}, {"plots", plots}, {"frames", b.frames}};
}

json converge_data(const ConvergeRun& c, const std::string& scene) {
  // A row per backend: its time to the error every curve reaches, and its last point.
  json table = {{"sort", "seconds_to_target"},
                {"columns",
                 {column("method", "backend", "", 0), column("seconds_to_target", "seconds to the target RMSE", "lower", 3),
                  column("spp", "last spp", "", 0), column("seconds", "its seconds", "lower", 3),
                  with_noise(column("rmse", "its RMSE", "lower", 4), c.truth_noise_rmse, "the truth's noise RMSE")}},
                {"floors", json::array()}};
  for (const ConvergenceCurve& curve : c.curves) {
    const ConvergencePoint& last = curve.points.back();
    table["rows"].push_back({{"method", curve.backend},
                             {"seconds_to_target", std::isfinite(curve.seconds_to_target) ? json(curve.seconds_to_target)
                                                                                          : json(nullptr)},
                             {"spp", last.spp},
                             {"seconds", last.seconds},
                             {"rmse", last.rmse}});
  }
  const std::string truth = c.truth_backend + " at " + std::to_string(c.truth_spp) + " spp";
  const ConvergencePlots plots = convergence_plots(c.curves, c.truth_noise_rmse, scene + " (truth: " + truth + ")");
  return {{"table", table}, {"plots", {plots.by_time, plots.by_samples}}, {"truth", truth}, {"target_rmse", c.target_rmse}};
}

/// The page's script, one concept a file, concatenated in this order into one <script>: each part
/// uses the helpers of those before it.
constexpr const char* kScriptParts[] = {"common.js",     "table.js",    "viewer.js", "sections.js",
                                        "navigation.js", "selftest.js", "main.js"};

std::string template_file(const std::string& name) {
  const auto& files = report_template_files();
  const auto it = files.find(name);
  if (it == files.end()) throw RuntimeFailure("report template " + name + " is not embedded in this build");
  return std::string(it->second);
}

void replace_once(std::string& text, const std::string& placeholder, const std::string& value) {
  const auto at = text.find(placeholder);
  if (at == std::string::npos) throw RuntimeFailure("report template: no " + placeholder + " in page.html");
  text.replace(at, placeholder.size(), value);
}

}  // namespace

std::string report_asset_folder(const ReportRun& run) { return "assets/" + run.id; }

std::string report_page(const ReportInputs& inputs) {
  json runs = json::array();
  for (const auto& run : inputs.runs) {
    json facts = json::array();
    for (const auto& [label, value] : run.facts) facts.push_back({label, value});
    json r = {{"id", run.id},       {"kind", run.kind()},   {"scene", run.scene},
              {"width", run.width}, {"height", run.height}, {"facts", facts}};
    const std::string assets = report_asset_folder(run);
    if (const auto* c = std::get_if<CompareRun>(&run.data))
      r.update(compare_data(*c, assets));
    else if (const auto* a = std::get_if<AnimateRun>(&run.data))
      r.update(animate_data(*a, assets));
    else if (const auto* b = std::get_if<BenchRun>(&run.data))
      r.update(bench_data(*b));
    else
      r.update(converge_data(std::get<ConvergeRun>(run.data), run.scene));
    runs.push_back(r);
  }
  // JSON inside <script>: '<' only occurs in strings there, where \u003c means the same and no
  // "</script>" or "<!--" can end the element early.
  std::string data;
  for (const char c : json{{"runs", runs}}.dump(-1, ' ', false, json::error_handler_t::replace))
    data += c == '<' ? std::string("\\u003c") : std::string(1, c);
  std::string page = template_file("page.html");
  replace_once(page, "/*@STYLE@*/", template_file("report.css"));
  std::string script;
  for (const char* part : kScriptParts) script += template_file(part) + "\n";
  replace_once(page, "/*@SCRIPT@*/", script);
  replace_once(page, "@DATA@", data);  // last: the data may hold any text
  return page;
}

}  // namespace glintlab
