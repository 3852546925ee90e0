#include "eval/report_inputs.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/image_io.hpp"
#include "core/png_header_check.hpp"

namespace glintlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A value inside a metrics file, with the way to it ("methods[2].rmse") for error messages.
class Field {
 public:
  Field(const json& value, const fs::path& file, std::string key) : value_(value), file_(file), key_(std::move(key)) {}

  [[nodiscard]] bool has(const std::string& name) const { return value_.is_object() && value_.contains(name); }
  [[nodiscard]] bool is_null() const { return value_.is_null(); }
  [[nodiscard]] Field operator[](const std::string& name) const {
    const std::string key = key_.empty() ? name : key_ + "." + name;
    if (!value_.is_object() || !value_.contains(name))
      fail(key, "is missing", "the key, as glintlab's compare, animate, bench and converge write it");
    return {value_.at(name), file_, key};
  }
  [[nodiscard]] std::vector<Field> elements() const {
    if (!value_.is_array()) fail(key_, "is " + shown(), "an array");
    std::vector<Field> all;
    for (std::size_t i = 0; i < value_.size(); ++i)
      all.emplace_back(value_[i], file_, key_ + "[" + std::to_string(i) + "]");
    return all;
  }
  /// The elements of an array that must hold at least one (a run's methods).
  [[nodiscard]] std::vector<Field> some_elements() const {
    std::vector<Field> all = elements();
    if (all.empty()) fail(key_, "is empty", "at least one entry");
    return all;
  }
  [[nodiscard]] double number() const {
    if (!value_.is_number()) fail(key_, "is " + shown(), "a number");
    return value_.get<double>();
  }
  /// An error, a time or a ratio: what glintlab writes is finite and at least 0.
  [[nodiscard]] double measure() const {
    const double v = number();
    if (!(v >= 0.0 && v <= std::numeric_limits<double>::max())) fail(key_, "is " + shown(), "a finite number >= 0");
    return v;
  }
  [[nodiscard]] int integer(int least = std::numeric_limits<int>::min(), int most = std::numeric_limits<int>::max()) const {
    std::string allowed = least == std::numeric_limits<int>::min() ? "an integer" : "an integer from " + std::to_string(least);
    if (most != std::numeric_limits<int>::max()) allowed += " to " + std::to_string(most);
    if (!value_.is_number_integer()) fail(key_, "is " + shown(), allowed);
    const auto v = value_.get<std::int64_t>();
    if (v < least || v > most) fail(key_, "is " + shown(), allowed);
    return static_cast<int>(v);
  }
  [[nodiscard]] std::string text() const {
    if (!value_.is_string()) fail(key_, "is " + shown(), "a string");
    return value_.get<std::string>();
  }
  /// A method's file name or a file name: used as a path inside the run's directory, so nothing that
  /// leaves it ('=' for variants: "podee.area=lens").
  [[nodiscard]] std::string file_name() const {
    const std::string name = text();
    const bool plain = !name.empty() && name[0] != '.' && std::all_of(name.begin(), name.end(), [](unsigned char c) {
      return std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '+' || c == '=';
    });
    if (!plain)
      fail(key_, "is " + shown(), "a plain name of letters, digits, '-', '_', '.', '+', '=' (not starting with '.')");
    return name;
  }
  [[nodiscard]] const fs::path& file() const { return file_; }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& what, const std::string& allowed) const {
    throw InputError(file_.string() + ": key '" + key + "' " + what + "; allowed: " + allowed);
  }
  [[nodiscard]] std::string shown() const {
    std::string s = value_.dump(-1, ' ', false, json::error_handler_t::replace);
    return s.size() > 40 ? s.substr(0, 40) + "..." : s;
  }

  const json& value_;
  fs::path file_;
  std::string key_;
};

std::string number_text(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4g", v);
  return s;
}

/// Label and value of the optional keys that describe a run, in display order.
std::vector<std::pair<std::string, std::string>> facts_of(const json& j) {
  static const std::vector<std::pair<const char*, const char*>> keys = {
      {"device", "device"},
      {"frame", "frame"},
      {"frames", "frames"},
      {"warmup", "warm-up frames"},
      {"reference_backend", "reference backend"},
      {"reference_filter", "reference pixel filter"},
      {"reference_max_depth", "reference path vertices lit"},
      {"reference_spp_min", "reference spp (least)"},
      {"reference_spp", "reference spp"},
      {"reference_passes", "reference passes"},
      {"reference_auto", "reference spp auto"},
      {"reference_noise_rmse", "reference noise RMSE"},
      {"reference_energy_error", "reference energy error (relative)"},
      {"flicker_floor", "flicker floor"},
      {"error_map_scale", "error map scale (full colour)"}};
  std::vector<std::pair<std::string, std::string>> facts;
  for (const auto& [key, label] : keys) {
    if (!j.contains(key)) continue;
    const json& v = j.at(key);
    if (v.is_string())
      facts.emplace_back(label, v.get<std::string>());
    else if (v.is_boolean())
      facts.emplace_back(label, v.get<bool>() ? "yes" : "no");
    else if (v.is_number())
      facts.emplace_back(label, number_text(v.get<double>()));
  }
  return facts;
}

/// The file name of a method's images or video: its "file" (since variants), else its name.
std::string method_file(const Field& method) {
  return method.has("file") ? method["file"].file_name() : method["method"].file_name();
}

/// The most frames a metrics file may claim: the CLI's --frames limit.
constexpr int kMaxFrames = 100000;

/// A file a run names must be a regular file inside the run's folder: the names are plain (no
/// '/', no '..'), and a symbolic link is refused, so that a report never publishes what a link
/// points to elsewhere. Images must decode and videos must be MP4s before anything is published.
void require_file(const fs::path& file, const Field& from) {
  const FileKind kind = file_kind(file, false);
  if (kind == FileKind::missing)
    throw InputError(file.string() + ": missing; " + from.file().string() +
                     " names it (a run's files are published together)");
  if (kind != FileKind::regular)
    throw InputError(file.string() + ": is " + std::string(describe(kind)) + "; " + from.file().string() +
                     " names it; allowed: a regular file inside the run's folder (a report copies no links)");
  const std::string extension = file.extension().string();
  if (extension == ".png") {
    try {
      if (!check_png_header(file)) throw InputError(file.string() + ": no PNG signature");
      (void)read_ldr_image(file);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + "; " + from.file().string() + " names it as a PNG image");
    }
  } else if (extension == ".mp4") {
    const std::string bytes = read_regular_file(file, "", kMaxBinaryFileBytes);
    if (bytes.size() < 12 || bytes.compare(4, 4, "ftyp") != 0)
      throw InputError(file.string() + ": not an MP4 video (no 'ftyp' box); " + from.file().string() + " names it");
  }
}

CompareRun read_compare(const Field& root, const fs::path& dir) {
  CompareRun run;
  run.reference_noise_rmse = root["reference_noise_rmse"].measure();
  run.error_map_scale = root["error_map_scale"].measure();
  for (const Field& m : root["methods"].some_elements()) {
    CompareRow& r = run.rows.emplace_back();
    r.method = m["method"].text();
    r.file = method_file(m);
    r.rmse = m["rmse"].measure();
    r.rmse_specular = m["rmse_specular"].measure();
    r.psnr = m["psnr"].number();
    r.max_error = m["max_error"].measure();
    r.energy_ratio = m["energy_ratio"].measure();
    r.energy_ratio_error = m["energy_ratio_error"].measure();
    r.energy_ratio_specular = m["energy_ratio_specular"].measure();
    r.energy_ratio_specular_error = m["energy_ratio_specular_error"].measure();
  }
  // FLIP and the sparkle distance since compare measures them; older outputs have neither.
  run.perceptual = root.has("reference_floor");
  if (run.perceptual) {
    const Field floor = root["reference_floor"];
    run.floor_flip_ldr = floor["flip_ldr"].measure();
    run.floor_flip_hdr = floor["flip_hdr"].measure();
    run.floor_sparkle_distance = floor["sparkle_distance"].measure();
    std::size_t i = 0;
    for (const Field& m : root["methods"].some_elements()) {
      CompareRow& r = run.rows[i++];
      r.flip_ldr = m["flip_ldr"].measure();
      r.flip_hdr = m["flip_hdr"].measure();
      r.sparkle_distance = m["sparkle_distance"].measure();
    }
  }
  const int columns = static_cast<int>(run.rows.size()) + 1;
  for (const Field& c : root["crops"].elements()) {
    WorstRegion& w = run.regions.emplace_back();
    w.file = c["file"].file_name();
    w.x = c["x"].integer(0);
    w.y = c["y"].integer(0);
    w.size = c["size"].integer(1);
    const fs::path strip = dir / w.file;
    require_file(strip, root);
    const auto dims = check_png_header(strip);
    if (!dims) throw InputError(strip.string() + ": not a PNG file; " + root.file().string() + " names it");
    // compare writes cell and gap since the report, label_height since it names the crops; older
    // outputs: the strip's height, 2-px gaps, no labels.
    w.label_height = c.has("label_height") ? c["label_height"].integer(0) : 0;
    w.cell = c.has("cell") ? c["cell"].integer(1) : static_cast<int>(dims->second) - w.label_height;
    w.gap = c.has("gap") ? c["gap"].integer(0) : 2;
    const std::int64_t width = static_cast<std::int64_t>(columns) * (static_cast<std::int64_t>(w.cell) + w.gap) - w.gap;
    const std::int64_t height = static_cast<std::int64_t>(w.cell) + w.label_height;
    if (dims->first != width || dims->second != height)
      throw InputError(strip.string() + ": is " + std::to_string(dims->first) + "x" + std::to_string(dims->second) +
                       "; allowed: the strip of " + std::to_string(columns) + " crops (reference and methods) of " +
                       std::to_string(w.cell) + " px, " + std::to_string(w.gap) + " px apart, above a " +
                       std::to_string(w.label_height) + "-px band of their names, that " + root.file().string() +
                       " describes: " + std::to_string(width) + "x" + std::to_string(height));
  }
  return run;
}

AnimateRun read_animate(const Field& root, const fs::path& dir) {
  AnimateRun run;
  run.frames = root["frames"].integer(1, kMaxFrames);
  run.reference_noise_rmse = root["reference_noise_rmse"].measure();
  run.flicker_floor = root["flicker_floor"].measure();
  std::vector<AnimateRun::Video> streams{{"reference", "reference"}};
  for (const Field& m : root["methods"].some_elements()) {
    AnimateRow& r = run.rows.emplace_back();
    r.method = m["method"].text();
    r.file = method_file(m);
    r.mean_rmse = m["mean_rmse"].measure();
    r.flicker = m["flicker"].measure();
    for (const Field& v : m["rmse_per_frame"].elements()) r.rmse_per_frame.push_back(v.measure());
    if (m.has("flicker_per_frame"))
      for (const Field& v : m["flicker_per_frame"].elements()) r.flicker_per_frame.push_back(v.measure());
    if (m.has("mean_flip_ldr")) {
      r.mean_flip_ldr = m["mean_flip_ldr"].measure();
      r.mean_flip_hdr = m["mean_flip_hdr"].measure();
      r.mean_sparkle_distance = m["mean_sparkle_distance"].measure();
    }
    streams.push_back({r.method, r.file});
  }
  run.perceptual = !run.rows.empty();
  for (const Field& m : root["methods"].some_elements()) run.perceptual &= m.has("mean_flip_ldr");
  // animate says whether it encoded videos ("video": "mp4"); then every stream has one, and a
  // missing one is an error like a missing image. Older outputs: the videos that are there.
  const bool encoded = root.has("video") && root["video"].text() == "mp4";
  for (const auto& s : streams)
    if (encoded || file_kind(dir / (s.file + ".mp4"), false) != FileKind::missing) run.videos.push_back(s);
  return run;
}

BenchRun read_bench(const Field& root) {
  BenchRun run;
  run.frames = root["frames"].integer(1, kMaxFrames);
  for (const Field& m : root["methods"].some_elements()) {
    BenchRow& r = run.rows.emplace_back();
    r.method = m["method"].text();  // "(unshaded)" too: bench shows no files by method name
    r.gpu_ms = m["gpu_ms_median"].measure();
    r.wall_ms = m["wall_ms_median"].measure();
  }
  return run;
}

ConvergeRun read_converge(const Field& root) {
  ConvergeRun run;
  run.truth_backend = root["truth_backend"].text();
  run.truth_spp = root["truth_spp"].integer(1);
  run.truth_noise_rmse = root["truth_noise_rmse"].measure();
  run.target_rmse = root["target_rmse"].measure();
  for (const Field& c : root["curves"].some_elements()) {
    ConvergenceCurve& curve = run.curves.emplace_back();
    curve.backend = c["backend"].text();
    for (const Field& p : c["points"].some_elements())
      curve.points.push_back({p["spp"].integer(1), p["seconds"].measure(), p["rmse"].measure(),
                              p["relative_rmse"].measure()});
    // null: the curve never reached the target.
    curve.seconds_to_target = c["seconds_to_target"].is_null() ? std::numeric_limits<double>::quiet_NaN()
                                                                : c["seconds_to_target"].measure();
  }
  return run;
}

json parse_json_file(const fs::path& file) {
  const std::string text = read_regular_file(file, "", kMaxTextFileBytes);
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(file.string() + ": not valid JSON (" + e.what() + "); allowed: the metrics glintlab writes");
  }
}

/// The kind of run a metrics file holds, by its keys; empty if none.
std::string kind_of(const json& j) {
  if (!j.is_object()) return "";
  if (j.contains("crops")) return "compare";
  if (j.contains("flicker_floor")) return "animate";
  if (j.contains("curves") && j.contains("truth_spp")) return "converge";
  if (j.contains("methods") && j["methods"].is_array() && !j["methods"].empty() && j["methods"][0].is_object() &&
      j["methods"][0].contains("wall_ms_median"))
    return "bench";
  return "";
}

/// A path-like id made of safe characters: it names the run's folder under assets/ and its URL.
std::string id_text(const fs::path& relative) {
  std::string id = relative.generic_string();
  for (char& c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' && c != '/') c = '_';
  return id;
}

/// The folder all inputs are in (for one input, the input itself): run ids are paths below it,
/// so that `report out/a/x out/b` names its runs a/x/... and b/..., as `report out` would.
fs::path common_folder(const std::vector<fs::path>& inputs) {
  fs::path common = fs::weakly_canonical(fs::absolute(inputs.front()));
  for (const fs::path& input : inputs) {
    const fs::path p = fs::weakly_canonical(fs::absolute(input));
    fs::path shared;
    for (auto a = common.begin(), b = p.begin(); a != common.end() && b != p.end() && *a == *b; ++a, ++b) shared /= *a;
    common = shared;
  }
  return common;
}

}  // namespace

const char* ReportRun::kind() const {
  static constexpr const char* names[] = {"compare", "animate", "bench", "converge"};
  return names[data.index()];
}

ReportInputs read_report_inputs(const std::vector<fs::path>& inputs) {
  if (inputs.empty())
    throw InputError("report: no INPUT given; allowed: output directories of compare, animate, bench, converge");
  for (const fs::path& input : inputs) {
    std::error_code ec;
    if (!fs::is_directory(input, ec))
      throw InputError(input.string() + ": " + (fs::exists(input, ec) ? "not a directory" : "no such directory") +
                       "; allowed: an output directory of compare, animate, bench or converge, or a folder above them");
  }
  const fs::path base = common_folder(inputs);
  ReportInputs result;
  std::map<std::string, int> ids;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(input, ec); it != fs::recursive_directory_iterator();
         it.increment(ec)) {
      if (ec) throw InputError(input.string() + ": cannot be searched: " + ec.message());
      const std::string name = it->path().filename().string();
      if (!name.empty() && name[0] == '.') {
        if (it->is_directory(ec)) it.disable_recursion_pending();
        continue;
      }
      if ((name == "metrics.json" || name == "bench.json" || name == "convergence.json") && it->is_regular_file(ec)) {
        if (it->is_symlink(ec))
          throw InputError(it->path().string() + ": is a symbolic link; allowed: a run's own metrics file (a report reads no links)");
        files.push_back(it->path());
      }
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      const json j = parse_json_file(file);
      const std::string kind = kind_of(j);
      if (kind.empty()) {
        result.warnings.push_back(file.string() +
                                  ": not a compare, animate, bench or converge output (no 'crops', no "
                                  "'flicker_floor', no methods[].wall_ms_median, no 'curves'); skipped");
        continue;
      }
      const Field root(j, file, "");
      ReportRun run;
      run.dir = file.parent_path();
      run.metrics = file;
      const fs::path relative = fs::weakly_canonical(fs::absolute(run.dir)).lexically_relative(base);
      std::string id = id_text(relative.empty() || relative == "." ? base.filename() : relative);
      if (const int seen = ids[id]++; seen > 0) id += "~" + std::to_string(seen + 1);
      run.id = id;
      run.scene = root["scene"].text();
      run.width = root["width"].integer(1);
      run.height = root["height"].integer(1);
      run.facts = facts_of(j);
      if (kind == "compare")
        run.data = read_compare(root, run.dir);
      else if (kind == "animate")
        run.data = read_animate(root, run.dir);
      else if (kind == "bench")
        run.data = read_bench(root);
      else
        run.data = read_converge(root);
      for (const auto& asset : report_assets(run)) require_file(run.dir / asset, root);
      result.runs.push_back(std::move(run));
    }
  }
  if (result.runs.empty()) {
    std::string list;
    for (const auto& i : inputs) list += (list.empty() ? "" : ", ") + i.string();
    throw InputError(list + ": no compare, animate, bench or converge output (metrics.json, bench.json, convergence.json) found");
  }
  return result;
}

std::vector<std::string> report_assets(const ReportRun& run) {
  std::vector<std::string> files;
  if (const auto* c = std::get_if<CompareRun>(&run.data)) {
    files.push_back("reference.png");
    for (const auto& r : c->rows) {
      files.push_back(r.file + ".png");
      files.push_back(r.file + "-error.png");
      if (c->perceptual) files.push_back(r.file + "-flip.png");  // written with FLIP since it is measured
    }
    for (const auto& w : c->regions) files.push_back(w.file);
  } else if (const auto* a = std::get_if<AnimateRun>(&run.data)) {
    for (const auto& v : a->videos) files.push_back(v.file + ".mp4");
  }
  return files;
}

}  // namespace glintlab
