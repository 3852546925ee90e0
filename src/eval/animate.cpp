#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numeric>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/image_io.hpp"
#include "core/output_stage.hpp"
#include "eval/commands.hpp"
#include "eval/outputs.hpp"

namespace glintlab {

namespace {

bool have_ffmpeg() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

/// Encodes numbered PNGs into an H.264 MP4; true on success.
bool encode_mp4(const std::filesystem::path& frames_dir, const std::filesystem::path& mp4) {
  AtomicFile file(mp4);
  const std::string cmd = "ffmpeg -nostdin -y -loglevel error -framerate 24 -i '" + (frames_dir / "%04d.png").string() +
                          "' -c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -f mp4 '" +
                          file.temp_path().string() + "'";
  if (std::system(cmd.c_str()) != 0) return false;
  file.commit();
  return true;
}

}  // namespace

void TemporalAccumulator::add_frame(const Image& method, const Image& reference, const MetricsReference* perceived) {
  rmse_per_frame_.push_back(rmse(method, reference));
  sparkle_per_frame_.push_back(sparkle_distance(method, reference, kSparkleBlock));
  if (perceived) {
    flip_ldr_per_frame_.push_back(flip::mean(perceived->flip_ldr_map(method)));
    flip_hdr_per_frame_.push_back(flip::mean(perceived->flip_hdr_map(method)));
  }
  flicker_.add_frame(method, reference);
}

namespace {
double mean_of(const std::vector<double>& values) {
  return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}
}  // namespace

TemporalMetrics TemporalAccumulator::result(const std::string& method) const {
  TemporalMetrics m{method, rmse_per_frame_, mean_of(rmse_per_frame_), flicker_.flicker(), flicker_.per_frame()};
  m.sparkle_per_frame = sparkle_per_frame_;
  m.flip_ldr_per_frame = flip_ldr_per_frame_;
  m.flip_hdr_per_frame = flip_hdr_per_frame_;
  m.mean_sparkle = mean_of(sparkle_per_frame_);
  m.mean_flip_ldr = mean_of(flip_ldr_per_frame_);
  m.mean_flip_hdr = mean_of(flip_hdr_per_frame_);
  return m;
}

void FlickerFloor::add_frame(const ReferenceFrame& reference) {
  halves_.add_frame(reference.even_passes, reference.odd_passes);
  noise_sum_ += reference.passes >= 2 ? reference.noise_rmse() : 0.0;
  spp_min_ = frames_ == 0 ? reference.spp : std::min(spp_min_, reference.spp);
  spp_max_ = std::max(spp_max_, reference.spp);
  ++frames_;
}

ReferenceFloor FlickerFloor::floor() const {
  std::vector<double> per_frame = halves_.per_frame();
  for (double& f : per_frame) f /= std::sqrt(2.0);
  return {halves_.flicker() / std::sqrt(2.0), frames_ > 0 ? noise_sum_ / frames_ : 0.0, spp_min_, spp_max_,
          std::move(per_frame)};
}

AnimateResult run_animate(Session& session, const std::vector<MethodChoice>& methods,
                                         const std::filesystem::path& out) {
  const int frames = session.frames();
  const Film& film = session.scene().film;
  const MetricsViewing viewing = metrics_viewing(session);
  std::vector<TemporalAccumulator> accumulators(methods.size());
  FlickerFloor floor;
  // Frames go to a staging folder first, so a failure half-way leaves no partial animation.
  const auto staging = out / ".frames-staging";
  std::filesystem::create_directories(out);
  remove_stale_temporaries(out);  // what a killed run left: AtomicFile's .tmp-<pid>-* files
  std::filesystem::remove_all(staging);
  char name[32];
  for (int f = 0; f < frames; ++f) {
    const Session::Rendered all = session.render_with_reference(methods, f);
    const std::vector<Frame>& rendered = all.methods;
    const Frame& reference = all.reference.mean;
    floor.add_frame(all.reference);
    const MetricsReference perceived(reference.total, reference.specular, viewing);
    std::snprintf(name, sizeof name, "%04d.png", f);
    write_png(staging / "reference" / name, tonemap_for_display(reference.total, film.exposure, film.bloom));
    for (std::size_t i = 0; i < methods.size(); ++i) {
      accumulators[i].add_frame(rendered[i].total, reference.total, &perceived);
      write_png(staging / methods[i].file_stem() / name,
                tonemap_for_display(rendered[i].total, film.exposure, film.bloom));
    }
  }
  const ReferenceFloor reference_floor = floor.floor();
  nlohmann::json json = run_metadata(session);
  json["frames"] = frames;
  json["reference_spp"] = reference_floor.spp_max;
  json["reference_spp_min"] = reference_floor.spp_min;
  json["reference_auto"] = session.options().spp_auto;
  json["reference_noise_rmse"] = reference_floor.noise_rmse;
  json["flicker_floor"] = reference_floor.flicker;
  json["flicker_floor_per_frame"] = reference_floor.flicker_per_frame;
  json["flicker_floor_definition"] =
      "flicker of the reference's even passes against its odd passes, over sqrt(2): the flicker a second "
      "independent reference would show against the first; smaller method differences are noise";
  json["flicker_definition"] = "mean over pixels, RGB channels and frames t>=1 of |(m_t - r_t) - (m_{t-1} - r_{t-1})|";
  json["sparkle_block"] = kSparkleBlock;
  json["flip_pixels_per_degree"] = viewing.pixels_per_degree;
  json["flip_display_exposure"] = viewing.display_exposure;
  json["flip_hdr_exposures"] = "automatic, from each frame's reference";
  std::vector<TemporalMetrics> results;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const auto& r = results.emplace_back(accumulators[i].result(methods[i].display_name()));
    json["methods"].push_back(
        {{"method", r.method},
         {"file", methods[i].file_stem()},  // <file>.mp4, or the folder frames-<file>
         {"mean_rmse", r.mean_rmse},
         {"flicker", r.flicker},
         {"rmse_per_frame", r.rmse_per_frame},
         {"flicker_per_frame", r.flicker_per_frame},
         {"mean_flip_ldr", r.mean_flip_ldr},
         {"mean_flip_hdr", r.mean_flip_hdr},
         {"mean_sparkle_distance", r.mean_sparkle},
         {"flip_ldr_per_frame", r.flip_ldr_per_frame},
         {"flip_hdr_per_frame", r.flip_hdr_per_frame},
         {"sparkle_distance_per_frame", r.sparkle_per_frame}});
  }
  // Publish: MP4s when ffmpeg is there, otherwise the PNG frames themselves.
  const bool ffmpeg = have_ffmpeg();
  std::vector<std::string> streams{"reference"};
  for (const auto& m : methods) streams.push_back(m.file_stem());
  for (const auto& s : streams) {
    if (ffmpeg && encode_mp4(staging / s, out / (s + ".mp4"))) continue;
    const auto target = out / ("frames-" + s);
    std::filesystem::remove_all(target);
    std::filesystem::rename(staging / s, target);
  }
  std::filesystem::remove_all(staging);
  json["video"] = ffmpeg ? "mp4" : "png frames (ffmpeg not installed)";
  write_text_file(out / "metrics.json", json.dump(2) + "\n");

  // The name column: 22 wide, wider for a longer name (a variant's).
  int width = 22;
  for (const auto& r : results) width = std::max(width, static_cast<int>(r.method.size()));
  std::printf("scene %s, %d frames, %dx%d, reference %d..%d spp\n%-*s %12s %12s %9s %9s %9s\n",
              session.scene().source.c_str(), frames, session.width(), session.height(), reference_floor.spp_min,
              reference_floor.spp_max, width, "method", "mean_rmse", "flicker", "flip", "hdr_flip", "sparkle");
  for (const auto& r : results)
    std::printf("%-*s %12.6f %12.6f %9.4f %9.4f %9.4f\n", width, r.method.c_str(), r.mean_rmse, r.flicker,
                r.mean_flip_ldr, r.mean_flip_hdr, r.mean_sparkle);
  std::printf("%-*s %12.6f %12.6f\n", width, "(reference floor)", reference_floor.noise_rmse, reference_floor.flicker);
  std::printf("written to %s/\n", out.string().c_str());
  return {results, reference_floor};
}

}  // namespace glintlab
