// docs/past-one-machine.md's recipes: a reference split into tiles by independent jobs (render
// --reference --tile, run by GNU parallel) and put back together by merge-tiles is the whole film's
// reference, and tiles that cannot be one frame are refused with nothing written; an animation's
// references rendered frame by frame as separate jobs into a shared cache are the ones animate uses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_fixture.hpp"
#include "core/image_io.hpp"
#include "test_scenes.hpp"

namespace fs = std::filesystem;
using glintlab::test::Cli;
using glintlab::test::read_bytes;
using glintlab::test::TestScene;

namespace {

// A Gaussian pixel filter: the pixels at a tile's edge weigh samples of the next tile's pixels.
const std::string kSampling = " -q --reference=16 --reference-filter gaussian:0.5 --width 23 --height 17";

double largest_difference(const glintlab::Image& a, const glintlab::Image& b) {
  double worst = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a.at(x, y)[c]) - b.at(x, y)[c]) / (1.0 + std::abs(double(b.at(x, y)[c]))));
  return worst;
}

}  // namespace

TEST_F(Cli, TilesRenderedByGnuParallelMergeIntoTheWholeFramesReference) {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0) GTEST_SKIP() << "GNU parallel is not installed";
  const std::string scene = " --scene '" + write("tiles.toml", TestScene::minimal().film(16, 16).toml()).string() + "'";
  // The whole film as one tile (its JSON too), and the recipe: four tiles as four parallel jobs.
  ASSERT_EQ(run_glintlab("render" + scene + kSampling + " --tile 0/1x1 -o '" + (scratch / "whole.exr").string() + "'").code, 0);
  const std::string recipe = "parallel --will-cite -j 2 '" GLINTLAB_BINARY "' render" + scene + kSampling +
                             " --tile {}/2x2 -o '" + (scratch / "tiles").string() + "/tile-{}.exr' ::: 0 1 2 3";
  ASSERT_EQ(std::system(("GLINTLAB_CACHE_DIR='" + cache().string() + "' " + recipe + " >/dev/null 2>&1").c_str()), 0)
      << recipe;
  std::string tiles;
  for (int i = 0; i < 4; ++i) tiles += " '" + (scratch / "tiles" / ("tile-" + std::to_string(i) + ".exr")).string() + "'";
  const auto merged = scratch / "merged.exr";
  const auto r = run_glintlab("merge-tiles" + tiles + " -o '" + merged.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;

  const auto whole = scratch / "whole.exr";
  for (const char* layer : {"", "specular", "standard_error", "stated_error"}) {
    const glintlab::Image a = glintlab::read_exr(merged, layer), b = glintlab::read_exr(whole, layer);
    ASSERT_EQ(a.width(), 23);
    ASSERT_EQ(a.height(), 17);
    // A tile's raster transform differs from the whole film's by float rounding only.
    EXPECT_LT(largest_difference(a, b), 1e-4) << "layer '" << layer << "'";
  }
  const auto merged_json = nlohmann::json::parse(read_bytes(scratch / "merged.json"));
  const auto whole_json = nlohmann::json::parse(read_bytes(scratch / "whole.json"));
  EXPECT_EQ(merged_json["identity"], whole_json["identity"]);
  for (const char* key : {"pass_luminance", "pass_luminance_specular"}) {
    ASSERT_EQ(merged_json[key].size(), 4u);
    for (std::size_t p = 0; p < 4; ++p)
      EXPECT_NEAR(merged_json[key][p].get<double>(), whole_json[key][p].get<double>(),
                  1e-4 * std::abs(whole_json[key][p].get<double>()) + 1e-9)
          << key << " of pass " << p;
  }
  const double luminance = whole_json["pass_luminance"][0].get<double>();
  EXPECT_GT(luminance, 0.0) << "a black frame would agree with anything";

  // Tiles that cannot be one frame: a gap, an overlap, another sampling, a file that is no tile.
  const auto tile = [&](int i) { return " '" + (scratch / "tiles" / ("tile-" + std::to_string(i) + ".exr")).string() + "'"; };
  expect_bad_input("merge-tiles" + tile(0) + tile(1) + tile(2), {"is in no tile", "pixels are missing"});
  expect_bad_input("merge-tiles" + tile(0) + tile(1) + tile(2) + tile(3) + tile(3), {"both cover pixel", "tile-3.exr"});
  ASSERT_EQ(run_glintlab("render" + scene + " -q --reference=4 --reference-filter gaussian:0.5 --width 23 --height 17"
                         " --tile 3/2x2 -o '" + (scratch / "other" / "tile-3.exr").string() + "'").code, 0);
  expect_bad_input("merge-tiles" + tile(0) + tile(1) + tile(2) + " '" + (scratch / "other" / "tile-3.exr").string() + "'",
                   {"other/tile-3.exr", "but", "share scene, frame, film, sampling"});
  expect_bad_input("merge-tiles" + tile(0) + " '" + (scratch / "whole.png").string() + "'", {"whole.png", "allowed: the .exr"});
  fs::remove(scratch / "tiles" / "tile-2.json");
  expect_bad_input("merge-tiles" + tile(0) + tile(1) + tile(2) + tile(3), {"tile-2.exr", "no ", "tile-2.json beside it"});
}

TEST_F(Cli, TileOptionsOutsideTheirRangeAreBadInput) {
  const std::string scene = " --scene '" + write("tiles.toml", TestScene::minimal().film(16, 16).toml()).string() + "'";
  expect_bad_input("render" + scene + " --reference=4 --tile 4/2x2", {"--tile 4/2x2", "0 <= INDEX < COLUMNS x ROWS"});
  expect_bad_input("render" + scene + " --reference=4 --tile 0/17x1", {"--tile 0/17x1", "1 <= COLUMNS <= 16"});
  expect_bad_input("render" + scene + " --reference=4 --tile two", {"--tile two", "not INDEX/COLUMNSxROWS"});
  expect_bad_input("render" + scene + " --reference=4 --tile -1/2x2", {"--tile -1/2x2", "not INDEX/COLUMNSxROWS"});
  expect_bad_input("render" + scene + " --tile 0/2x2", {"--tile 0/2x2", "with --reference only"});
  expect_bad_input("render" + scene + " --reference=auto --tile 0/2x2", {"--tile with --spp auto", "--spp N"});
}

TEST_F(Cli, FramesRenderedAsSeparateJobsAreTheReferencesAnimateUses) {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0) GTEST_SKIP() << "GNU parallel is not installed";
  const std::string scene = " --scene '" + write("frames.toml", TestScene::minimal().film(16, 16).toml()).string() + "'";
  const std::string sampling = " -q --reference=4 --frames 2 --width 12 --height 8";
  const std::string recipe = "parallel --will-cite -j 2 '" GLINTLAB_BINARY "' render" + scene + sampling + " --frame {} -o '" +
                             (scratch / "refs").string() + "/frame-{}.exr' ::: 0 1";
  ASSERT_EQ(std::system(("GLINTLAB_CACHE_DIR='" + cache().string() + "' " + recipe + " >/dev/null 2>&1").c_str()), 0)
      << recipe;
  std::map<fs::path, fs::file_time_type> entries;
  for (const auto& e : fs::directory_iterator(cache()))
    if (e.path().extension() == ".exr") entries[e.path()] = fs::last_write_time(e.path());
  ASSERT_EQ(entries.size(), 2u) << "one cached reference per frame";
  // animate with the same sampling finds every frame's reference: it stores none again.
  const auto r = run_glintlab("animate" + scene + " -q --spp 4 --frames 2 --width 12 --height 8 -o '" +
                              (scratch / "animate").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  std::size_t after = 0;
  for (const auto& e : fs::directory_iterator(cache()))
    if (e.path().extension() == ".exr") {
      ++after;
      ASSERT_TRUE(entries.count(e.path())) << "animate rendered a reference the jobs had: " << e.path();
      EXPECT_EQ(fs::last_write_time(e.path()), entries[e.path()]) << e.path();
    }
  EXPECT_EQ(after, entries.size());
}
