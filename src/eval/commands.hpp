#pragma once
// The evaluation drivers behind `glintlab compare`, `animate` and `bench`.
#include <filesystem>
#include <vector>

#include "core/metrics.hpp"
#include "eval/session.hpp"

namespace glintlab {

struct MethodMetrics {
  std::string method;
  ImageMetrics metrics;
};

/// Reference and every method on one frame: images, error maps, worst-region crops,
/// metrics.csv and metrics.json under `out`. Returns the metrics (also printed to stdout).
std::vector<MethodMetrics> run_compare(Session& session, const std::vector<MethodChoice>& methods,
                                       const std::filesystem::path& out, int frame = 0);

struct TemporalMetrics {
  std::string method;
  std::vector<double> rmse_per_frame;
  double mean_rmse = 0;
  double flicker = 0;
  std::vector<double> flicker_per_frame;  ///< of each frame t >= 1 against t - 1 (flicker is their mean)
  /// Per frame and their means: the sparkle distance, and (when frames were added with a
  /// MetricsReference) LDR-FLIP and HDR-FLIP; empty vectors and 0 otherwise.
  std::vector<double> sparkle_per_frame, flip_ldr_per_frame, flip_hdr_per_frame;
  double mean_sparkle = 0, mean_flip_ldr = 0, mean_flip_hdr = 0;
};

/// One method's error over a sequence, added frame by frame: the RMSE and sparkle distance of
/// each frame, their means, and the flicker (FlickerAccumulator); with `perceived` (the frame's
/// reference prepared for FLIP) also each frame's LDR- and HDR-FLIP.
class TemporalAccumulator {
 public:
  void add_frame(const Image& method, const Image& reference, const MetricsReference* perceived = nullptr);
  [[nodiscard]] TemporalMetrics result(const std::string& method) const;

 private:
  std::vector<double> rmse_per_frame_, sparkle_per_frame_, flip_ldr_per_frame_, flip_hdr_per_frame_;
  FlickerAccumulator flicker_;
};

/// What the reference of an animation allows one to resolve.
struct ReferenceFloor {
  double flicker = 0;     ///< the flicker a second independent reference would show against the first
  double noise_rmse = 0;  ///< the reference's noise RMSE, mean over frames
  int spp_min = 0, spp_max = 0;
  std::vector<double> flicker_per_frame;  ///< the floor of each frame t >= 1
};

/// The flicker floor from the even and odd passes of each frame's reference: two independent
/// half-references, whose flicker against each other is sqrt(2) times that of two full ones
/// (their noise has twice the variance), so the floor is that flicker over sqrt(2).
class FlickerFloor {
 public:
  void add_frame(const ReferenceFrame& reference);
  [[nodiscard]] ReferenceFloor floor() const;

 private:
  FlickerAccumulator halves_;
  double noise_sum_ = 0;
  int frames_ = 0, spp_min_ = 0, spp_max_ = 0;
};

struct AnimateResult {
  std::vector<TemporalMetrics> methods;
  ReferenceFloor reference;
};

/// The camera path for every method and the reference: per-frame RMSE and flicker, the flicker
/// floor of the reference, an MP4 per method when ffmpeg is installed (PNG frames otherwise),
/// metrics.json under `out`.
AnimateResult run_animate(Session& session, const std::vector<MethodChoice>& methods, const std::filesystem::path& out);

struct BenchResult {
  std::string method;
  double gpu_ms_median = 0;   ///< GL_TIME_ELAPSED, median over frames
  double wall_ms_median = 0;  ///< draw + glFinish on the CPU clock, median
  int frames = 0;
};

/// Times every method's frame and the unshaded floor (with `floor_breakdown`, also the floor into
/// cheaper colour targets: two RGBA16F, one RGBA32F, depth only); writes bench.json under `out` if
/// it is not empty.
std::vector<BenchResult> run_bench(Session& session, const std::vector<MethodChoice>& methods, int frames, int warmup,
                                   const std::filesystem::path& out, bool floor_breakdown = false);

}  // namespace glintlab
