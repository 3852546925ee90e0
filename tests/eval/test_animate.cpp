// `glintlab animate` (run_animate) on a tiny scene: its per-frame RMSE, flicker and reference
// floor against the same quantities computed here from the frames themselves, and what it writes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "eval/commands.hpp"
#include "eval/outputs.hpp"
#include "scratch_directory.hpp"
#include "test_scenes.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr int kFrames = 3;

/// A glossy sphere on a plane under a sphere light, orbited over three frames: highlights that
/// move, so that every method's error changes from frame to frame.
std::string orbiting_sphere() {
  return TestScene()
      .film(24, 16)
      .camera({0, 1, 3}, {0, 0.3, 0}, 40, {{"path", TomlKeys{{"type", "orbit"}, {"degrees", 20}, {"frames", kFrames}}}})
      .material("glossy", {{"alpha", 0.05}, {"f0", 0.9}, {"diffuse", 0.1}})
      .sphere("glossy", {{"radius", 0.4}, {"translate", {0, 0.4, 0}}, {"segments", 24}})
      .plane("glossy", {{"size", 4}})
      .sphere_light({1, 2, 1}, 0.2, 30, {{"visible", false}})
      .toml();
}

/// Root mean square over pixels and RGB channels of a - b.
double rms_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) sum += std::pow(double(a.pixels()[i][c]) - double(b.pixels()[i][c]), 2);
  return std::sqrt(sum / (3.0 * double(a.pixel_count())));
}

/// Mean over pixels, RGB channels and frames t >= 1 of |(a_t - b_t) - (a_{t-1} - b_{t-1})|.
double mean_change_of_difference(const std::vector<Image>& a, const std::vector<Image>& b) {
  double sum = 0, count = 0;
  for (std::size_t t = 1; t < a.size(); ++t)
    for (std::size_t i = 0; i < a[t].pixel_count(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double now = double(a[t].pixels()[i][c]) - b[t].pixels()[i][c];
        const double before = double(a[t - 1].pixels()[i][c]) - b[t - 1].pixels()[i][c];
        sum += std::abs(now - before);
        count += 1;
      }
  return sum / count;
}

}  // namespace

TEST(Animate, MetricsAreThoseOfTheFramesItRendered) {
  const ScratchDirectory dir;
  {
    std::ofstream(dir / "orbit.toml") << orbiting_sphere();
  }
  CommonOptions options;
  options.scene = (dir / "orbit.toml").string();
  options.spp = 16;  // 4 passes of 2 x 2: the even and odd halves of the floor have 2 passes each
  options.no_cache = true;
  options.quiet = true;
  const auto methods = resolve_methods("conventional,vlachos", {});
  Session session(options);
  ASSERT_EQ(session.frames(), kFrames);
  const AnimateResult result = run_animate(session, methods, dir / "out");

  // The same frames again (rendering is deterministic; the reference's seed is the frame).
  std::vector<ReferenceFrame> references;
  std::vector<Image> reference_images, evens, odds;
  for (int t = 0; t < kFrames; ++t) {
    references.push_back(session.reference(t));
    reference_images.push_back(references.back().mean.total);
    evens.push_back(references.back().even_passes);
    odds.push_back(references.back().odd_passes);
  }
  ASSERT_EQ(result.methods.size(), methods.size());
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const TemporalMetrics& m = result.methods[i];
    EXPECT_EQ(m.method, methods[i].method->id);
    ASSERT_EQ(m.rmse_per_frame.size(), static_cast<std::size_t>(kFrames));
    std::vector<Image> frames;
    double mean = 0;
    for (int t = 0; t < kFrames; ++t) {
      frames.push_back(session.render(methods[i], t).total);
      const double expected = rms_difference(frames.back(), reference_images[t]);
      EXPECT_GT(expected, 0.0) << m.method << " frame " << t;
      EXPECT_NEAR(m.rmse_per_frame[t], expected, 1e-9 * expected) << m.method << " frame " << t;
      mean += expected / kFrames;
    }
    EXPECT_NEAR(m.mean_rmse, mean, 1e-9 * mean) << m.method;
    // FLIP, HDR-FLIP and the sparkle distance of every frame, as compare measures one.
    ASSERT_EQ(m.sparkle_per_frame.size(), static_cast<std::size_t>(kFrames));
    ASSERT_EQ(m.flip_ldr_per_frame.size(), static_cast<std::size_t>(kFrames));
    ASSERT_EQ(m.flip_hdr_per_frame.size(), static_cast<std::size_t>(kFrames));
    double flip_mean = 0;
    for (int t = 0; t < kFrames; ++t) {
      const MetricsReference perceived(reference_images[t], references[t].mean.specular, metrics_viewing(session));
      const ImageMetrics expected = perceived.measure(frames[t], frames[t]);
      EXPECT_DOUBLE_EQ(m.sparkle_per_frame[t], expected.sparkle_distance) << m.method << " frame " << t;
      EXPECT_DOUBLE_EQ(m.flip_ldr_per_frame[t], expected.flip_ldr) << m.method << " frame " << t;
      EXPECT_DOUBLE_EQ(m.flip_hdr_per_frame[t], expected.flip_hdr) << m.method << " frame " << t;
      EXPECT_GT(expected.flip_hdr, 0.0) << m.method << " frame " << t;
      flip_mean += expected.flip_ldr / kFrames;
    }
    EXPECT_NEAR(m.mean_flip_ldr, flip_mean, 1e-12) << m.method;
    const double flicker = mean_change_of_difference(frames, reference_images);
    EXPECT_GT(flicker, 0.0) << m.method;
    EXPECT_NEAR(m.flicker, flicker, 1e-6 * flicker) << m.method;
    // Per frame: frame t against t - 1 alone; flicker is their mean.
    ASSERT_EQ(m.flicker_per_frame.size(), static_cast<std::size_t>(kFrames - 1));
    double per_frame_mean = 0;
    for (int t = 1; t < kFrames; ++t) {
      const double expected = mean_change_of_difference({frames[t - 1], frames[t]}, {reference_images[t - 1], reference_images[t]});
      EXPECT_NEAR(m.flicker_per_frame[t - 1], expected, 1e-6 * expected) << m.method << " frame " << t;
      per_frame_mean += m.flicker_per_frame[t - 1] / (kFrames - 1);
    }
    EXPECT_NEAR(per_frame_mean, m.flicker, 1e-9 * m.flicker) << m.method;
  }
  // The floor: the flicker of the even passes against the odd ones, over sqrt(2), and the noise
  // of the references (the root mean square of their per-pixel standard errors), averaged.
  const double floor = mean_change_of_difference(evens, odds) / std::sqrt(2.0);
  EXPECT_GT(floor, 0.0);
  EXPECT_NEAR(result.reference.flicker, floor, 1e-6 * floor);
  ASSERT_EQ(result.reference.flicker_per_frame.size(), static_cast<std::size_t>(kFrames - 1));
  for (int t = 1; t < kFrames; ++t) {
    const double expected = mean_change_of_difference({evens[t - 1], evens[t]}, {odds[t - 1], odds[t]}) / std::sqrt(2.0);
    EXPECT_NEAR(result.reference.flicker_per_frame[t - 1], expected, 1e-6 * expected) << "frame " << t;
  }
  double noise = 0;
  for (const auto& r : references) noise += rms_difference(r.standard_error, Image(24, 16)) / kFrames;
  EXPECT_NEAR(result.reference.noise_rmse, noise, 1e-9 * noise);
  EXPECT_EQ(result.reference.spp_min, 16);
  EXPECT_EQ(result.reference.spp_max, 16);

  // What it wrote: the metrics it returned, and a stream (an MP4 or PNG frames) per method and
  // for the reference; no staging folder left.
  std::ifstream in(dir / "out" / "metrics.json");
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json.at("frames"), kFrames);
  EXPECT_EQ(json.at("width"), 24);
  EXPECT_EQ(json.at("height"), 16);
  EXPECT_EQ(json.at("scene"), options.scene);
  EXPECT_DOUBLE_EQ(json.at("flicker_floor").get<double>(), result.reference.flicker);
  EXPECT_EQ(json.at("flicker_floor_per_frame").get<std::vector<double>>(), result.reference.flicker_per_frame);
  ASSERT_EQ(json.at("methods").size(), methods.size());
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const auto& m = json.at("methods")[i];
    EXPECT_EQ(m.at("method"), result.methods[i].method);
    EXPECT_DOUBLE_EQ(m.at("mean_rmse").get<double>(), result.methods[i].mean_rmse);
    EXPECT_DOUBLE_EQ(m.at("flicker").get<double>(), result.methods[i].flicker);
    EXPECT_EQ(m.at("rmse_per_frame").get<std::vector<double>>(), result.methods[i].rmse_per_frame);
    EXPECT_EQ(m.at("flicker_per_frame").get<std::vector<double>>(), result.methods[i].flicker_per_frame);
    EXPECT_EQ(m.at("flip_hdr_per_frame").get<std::vector<double>>(), result.methods[i].flip_hdr_per_frame);
    EXPECT_EQ(m.at("sparkle_distance_per_frame").get<std::vector<double>>(), result.methods[i].sparkle_per_frame);
    EXPECT_DOUBLE_EQ(m.at("mean_flip_ldr").get<double>(), result.methods[i].mean_flip_ldr);
  }
  const bool mp4 = json.at("video") == "mp4";
  for (const std::string stream : {"reference", "conventional", "vlachos"}) {
    if (mp4) {
      EXPECT_TRUE(std::filesystem::exists(dir / "out" / (stream + ".mp4"))) << stream;
    } else {
      for (const char* frame : {"0000.png", "0001.png", "0002.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / "out" / ("frames-" + stream) / frame)) << stream << " " << frame;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / ".frames-staging"));
}
