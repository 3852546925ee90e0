#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numeric>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/image_io.hpp"
#include "eval/commands.hpp"

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

std::vector<TemporalMetrics> run_animate(Session& session, const std::vector<MethodChoice>& methods,
                                         const std::filesystem::path& out) {
  const int frames = session.frames();
  const Film& film = session.scene().film;
  std::vector<FlickerAccumulator> flicker(methods.size());
  std::vector<TemporalMetrics> results(methods.size());
  // Frames go to a staging folder first, so a failure half-way leaves no partial animation.
  const auto staging = out / ".frames-staging";
  std::filesystem::remove_all(staging);
  char name[32];
  for (int f = 0; f < frames; ++f) {
    const Frame reference = session.reference(f);
    std::snprintf(name, sizeof name, "%04d.png", f);
    write_png(staging / "reference" / name, tonemap_for_display(reference.total, film.exposure, film.bloom));
    for (std::size_t i = 0; i < methods.size(); ++i) {
      const Frame frame = session.render(methods[i], f);
      flicker[i].add_frame(frame.total, reference.total);
      results[i].rmse_per_frame.push_back(rmse(frame.total, reference.total));
      write_png(staging / methods[i].method->id / name, tonemap_for_display(frame.total, film.exposure, film.bloom));
    }
  }
  nlohmann::json json;
  json["scene"] = session.scene().source;
  json["frames"] = frames;
  json["width"] = session.width();
  json["height"] = session.height();
  json["reference_spp"] = session.reference_settings().spp;
  json["device"] = session.context().info().renderer;
  json["flicker_definition"] = "mean over pixels, RGB channels and frames t>=1 of |(m_t - r_t) - (m_{t-1} - r_{t-1})|";
  for (std::size_t i = 0; i < methods.size(); ++i) {
    auto& r = results[i];
    r.method = methods[i].method->id;
    r.mean_rmse = std::accumulate(r.rmse_per_frame.begin(), r.rmse_per_frame.end(), 0.0) / frames;
    r.flicker = flicker[i].flicker();
    json["methods"].push_back(
        {{"method", r.method}, {"mean_rmse", r.mean_rmse}, {"flicker", r.flicker}, {"rmse_per_frame", r.rmse_per_frame}});
  }
  // Publish: MP4s when ffmpeg is there, otherwise the PNG frames themselves.
  const bool ffmpeg = have_ffmpeg();
  std::vector<std::string> streams{"reference"};
  for (const auto& m : methods) streams.push_back(m.method->id);
  for (const auto& s : streams) {
    if (ffmpeg && encode_mp4(staging / s, out / (s + ".mp4"))) continue;
    const auto target = out / ("frames-" + s);
    std::filesystem::remove_all(target);
    std::filesystem::rename(staging / s, target);
  }
  std::filesystem::remove_all(staging);
  json["video"] = ffmpeg ? "mp4" : "png frames (ffmpeg not installed)";
  write_text_file(out / "metrics.json", json.dump(2) + "\n");

  std::printf("scene %s, %d frames, %dx%d, reference %d spp\n%-22s %12s %12s\n", session.scene().source.c_str(), frames,
              session.width(), session.height(), session.reference_settings().spp, "method", "mean_rmse", "flicker");
  for (const auto& r : results) std::printf("%-22s %12.6f %12.6f\n", r.method.c_str(), r.mean_rmse, r.flicker);
  std::printf("written to %s/\n", out.string().c_str());
  return results;
}

}  // namespace glintlab
