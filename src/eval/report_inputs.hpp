#pragma once
// What `glintlab report` reads: the output directories of compare, animate, bench and converge,
// found by searching the inputs for metrics.json, bench.json and convergence.json and told apart by
// their keys. Everything
// is checked before the report writes a byte: a missing key, a broken file or a missing image
// throws InputError naming the file and the key.
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "eval/convergence_curve.hpp"

namespace glintlab {

struct CompareRow {
  std::string method;  ///< display name: an id or a variant's name, "podee{area=lens}"
  std::string file;    ///< its images: <file>.png, <file>-error.png
  double rmse = 0, rmse_specular = 0, psnr = 0, max_error = 0;
  double energy_ratio = 0, energy_ratio_error = 0;
  double energy_ratio_specular = 0, energy_ratio_specular_error = 0;
  double flip_ldr = 0, flip_hdr = 0, sparkle_distance = 0;  ///< absent in outputs older than them
};

/// One worst-region strip of compare: crops of the reference, then of each method in order, each
/// `cell` pixels square, `gap` pixels apart, above a band `label_height` pixels tall holding their
/// names (0: none).
struct WorstRegion {
  std::string file;
  int x = 0, y = 0, size = 0;
  int cell = 0, gap = 0, label_height = 0;
};

struct CompareRun {
  std::vector<CompareRow> rows;
  std::vector<WorstRegion> regions;
  double reference_noise_rmse = 0;
  double error_map_scale = 0;
  /// FLIP and the sparkle distance: in every row, and the two half-references' values
  /// (compare's reference_floor); false for outputs older than them.
  bool perceptual = false;
  double floor_flip_ldr = 0, floor_flip_hdr = 0, floor_sparkle_distance = 0;
};

struct AnimateRow {
  std::string method;  ///< display name
  std::string file;    ///< its video: <file>.mp4
  double mean_rmse = 0, flicker = 0;
  double mean_flip_ldr = 0, mean_flip_hdr = 0, mean_sparkle_distance = 0;  ///< absent in older outputs
  std::vector<double> rmse_per_frame;
  std::vector<double> flicker_per_frame;  ///< frames 1 .. frames - 1; empty in outputs older than it
};

struct AnimateRun {
  std::vector<AnimateRow> rows;
  int frames = 0;
  double reference_noise_rmse = 0;  ///< mean over frames
  double flicker_floor = 0;
  bool perceptual = false;  ///< every row has the FLIP and sparkle means
  /// The MP4 of each stream ("reference", then the methods) that exists; others have none (animate
  /// writes PNG frames instead when ffmpeg is missing or fails).
  struct Video {
    std::string name;  ///< "reference" or the method's display name
    std::string file;  ///< <file>.mp4
  };
  std::vector<Video> videos;
};

struct BenchRow {
  std::string method;
  double gpu_ms = 0, wall_ms = 0;
};

struct BenchRun {
  std::vector<BenchRow> rows;
  int frames = 0;
};

struct ConvergeRun {
  std::vector<ConvergenceCurve> curves;
  std::string truth_backend;
  int truth_spp = 0;
  double truth_noise_rmse = 0, target_rmse = 0;
};

/// One output directory's run.
struct ReportRun {
  std::string id;                 ///< unique in the report, path-like: "spheres", "area-lights/disk-0.1/ltc"
  std::filesystem::path dir;      ///< the output directory
  std::filesystem::path metrics;  ///< the JSON file it was read from
  std::string scene;
  int width = 0, height = 0;
  /// Label and value of what describes the run (device, reference samples, ...), in display order.
  std::vector<std::pair<std::string, std::string>> facts;
  std::variant<CompareRun, AnimateRun, BenchRun, ConvergeRun> data;

  [[nodiscard]] const char* kind() const;
};

struct ReportInputs {
  std::vector<ReportRun> runs;
  std::vector<std::string> warnings;  ///< files skipped: metrics of no known kind
};

/// Searches each input directory recursively (hidden folders skipped) for metrics.json,
/// bench.json and convergence.json, in path order. Throws InputError for an input that is not a directory, a file that
/// is not JSON or misses a key of its kind, a file it names that is missing, or no run at all.
ReportInputs read_report_inputs(const std::vector<std::filesystem::path>& inputs);

/// The file names a run's section shows, in its directory: images, error maps, strips, videos.
std::vector<std::string> report_assets(const ReportRun& run);

}  // namespace glintlab
