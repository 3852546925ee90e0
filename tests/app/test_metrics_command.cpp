// `glintlab metrics` end to end, and compare's perceptual metrics read back through it: the same
// numbers from the files as compare measured from its frames.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "app/cli_fixture.hpp"
#include "core/colour.hpp"
#include "core/flip_validation_pairs.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "test_scenes.hpp"

namespace fs = std::filesystem;
using glintlab::test::Cli;
using glintlab::test::CliResult;
using glintlab::test::read_bytes;
using glintlab::test::TestScene;

namespace glintlab {
namespace {

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(read_bytes(p)); }

TEST_F(Cli, MetricsOfTwoFilesAreTheLibrarysAndBadPairsExitWith2) {
  const Image reference = test::with_sparkles(test::flip_ramp(0.5f), glm::vec3(20.0f));
  const Image blurred = test::box_blurred(reference);
  write_exr(scratch / "ref.exr", {{"", &reference}});
  write_exr(scratch / "test.exr", {{"", &blurred}});
  CliResult r = run_glintlab("metrics '" + (scratch / "test.exr").string() + "' '" + (scratch / "ref.exr").string() +
                             "' --ppd 40 --flip-map '" + (scratch / "map.png").string() + "' -o '" +
                             (scratch / "m.json").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json m = read_json(scratch / "m.json");
  EXPECT_NEAR(m.at("rmse").get<double>(), rmse(blurred, reference), 1e-9);
  EXPECT_NEAR(m.at("sparkle_distance").get<double>(), sparkle_distance(blurred, reference, kSparkleBlock), 1e-9);
  const flip::Exposures e = flip::automatic_exposures(reference);
  EXPECT_NEAR(m.at("flip_hdr").get<double>(), flip::mean(flip::HdrReference(reference, 40.0, e).error_map(blurred)), 1e-9);
  EXPECT_EQ(m.at("hdr_exposures").at("count").get<int>(), e.count);
  EXPECT_TRUE(fs::is_regular_file(scratch / "map.png"));

  // Refused: exit 2, the message names the file or flag and what is allowed, and no JSON or map written.
  const fs::path refused = scratch / "refused.json";
  auto expect_refused = [&](const std::string& args, std::initializer_list<const char*> fragments) {
    const CliResult bad = run_glintlab(args + " -o '" + refused.string() + "'");
    EXPECT_EQ(bad.code, 2) << args << "\n" << bad.err;
    for (const char* f : fragments) EXPECT_NE(bad.err.find(f), std::string::npos) << "'" << f << "' not in: " << bad.err;
    EXPECT_FALSE(fs::exists(refused)) << args;
  };
  const std::string exr = " '" + (scratch / "test.exr").string() + "' '" + (scratch / "ref.exr").string() + "'";
  const Image small(8, 8);
  write_exr(scratch / "small.exr", {{"", &small}});
  write_png(scratch / "picture.png", small);
  expect_refused("metrics '" + (scratch / "small.exr").string() + "' '" + (scratch / "ref.exr").string() + "'",
                   {"small.exr", "8x8", "128x128", "the same size"});
  expect_refused("metrics '" + (scratch / "picture.png").string() + "' '" + (scratch / "ref.exr").string() + "'",
                   {"picture.png", "different kinds", "both .exr or both .png"});
  expect_refused("metrics" + exr + " --hdr-exposures 2,1,4", {"--hdr-exposures '2,1,4'", "START <= STOP"});
  expect_refused("metrics" + exr + " --hdr-exposures 0,1", {"--hdr-exposures '0,1'", "START,STOP,COUNT"});
  expect_refused("metrics '" + (scratch / "picture.png").string() + "' '" + (scratch / "picture.png").string() +
                       "' --hdr-exposures 0,1,2",
                   {"--hdr-exposures", "radiance (.exr)"});
  expect_refused("metrics" + exr + " --flip-map '" + (scratch / "map.jpg").string() + "'", {"map.jpg", ".png"});
  Image nan = reference;
  nan.at(3, 5) = glm::vec3(std::nanf(""));
  write_exr(scratch / "nan.exr", {{"", &nan}});
  expect_refused("metrics '" + (scratch / "nan.exr").string() + "' '" + (scratch / "ref.exr").string() + "'",
                   {"nan.exr", "pixel (3, 5)", "finite"});
  EXPECT_FALSE(fs::exists(scratch / "map.jpg"));
}

TEST_F(Cli, CompareMeasuresFlipAndSparklesAsTheMetricsCommandDoesFromItsFiles) {
  const fs::path scene = write("s.toml", TestScene::minimal().film(48, 32).toml());
  const fs::path out = scratch / "cmp";
  CliResult r = run_glintlab("compare --no-cache -q --spp 16 --ppd 30 --methods conventional --scene '" +
                             scene.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json json = read_json(out / "metrics.json");
  EXPECT_EQ(json.at("flip_pixels_per_degree").get<double>(), 30.0);
  EXPECT_TRUE(json.at("reference_floor").contains("flip_hdr"));
  EXPECT_TRUE(fs::is_regular_file(out / "conventional-flip.png"));
  EXPECT_NE(read_bytes(out / "metrics.csv").find(",flip_ldr,flip_hdr,sparkle_distance\n"), std::string::npos);
  const nlohmann::json& row = json.at("methods")[0];
  r = run_glintlab("metrics '" + (out / "conventional.exr").string() + "' '" + (out / "reference.exr").string() +
                   "' --ppd 30 --display-exposure " + std::to_string(json.value("flip_display_exposure", 0.0)) +
                   " -o '" + (scratch / "m.json").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json m = read_json(scratch / "m.json");
  for (const char* key : {"flip_ldr", "flip_hdr", "sparkle_distance", "rmse"})
    EXPECT_NEAR(m.at(key).get<double>(), row.at(key).get<double>(), 1e-6) << key;
  EXPECT_GT(row.at("flip_ldr").get<double>(), 0.0);
}

}  // namespace
}  // namespace glintlab
