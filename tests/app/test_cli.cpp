// The CLI end to end: every class of bad input gets exit code 2, a message naming what is wrong,
// and no output file; the same command writes identical files twice.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/hash.hpp"
#include "core/image_io.hpp"
#include "scene/lights/environment_map.hpp"
#include "app/cli_fixture.hpp"
#include "test_scenes.hpp"

namespace fs = std::filesystem;
using glintlab::test::Cli;
using glintlab::test::CliResult;
using glintlab::test::read_bytes;
using glintlab::test::TestScene;

namespace {

const std::string kScene = TestScene::minimal().film(16, 16).toml();

}  // namespace

TEST_F(Cli, BadInputClassesExitWith2AndWriteNothing) {
  const auto missing = (scratch / "missing.toml").string();
  expect_bad_input("render --scene '" + missing + "'", {"missing.toml", "does not exist"});
  expect_bad_input("render --scene '" + write("malformed.toml", "[film\n").string() + "'", {"malformed.toml:1", "malformed"});
  expect_bad_input("render --scene '" + write("unknown.toml", TestScene::minimal().film(16, 16).table("camera", {{"foo", 1}}).toml()).string() + "'", {"'foo'", "not a known key"});
  expect_bad_input("render --scene '" + write("type.toml", TestScene::minimal().table("film", {{"width", 1.5}}).toml()).string() + "'", {"width", "not an integer"});
  expect_bad_input("render --scene '" + write("range.toml", TestScene::minimal().film(16, 16).sphere_light({0, 0, 0}, -1, 1).toml()).string() + "'",
                   {"radius", "out of range"});
  expect_bad_input("render --scene '" + write("mesh.toml", TestScene::minimal().film(16, 16).shape("mesh", "m", {{"file", "nope.obj"}}).toml()).string() + "'",
                   {"nope.obj"});
  expect_bad_input("render --scene builtin:nothing", {"builtin:nothing", "spheres"});
  expect_bad_input("render --method magic", {"unknown method 'magic'", "conventional"});
  expect_bad_input("render --method tokuyoshi --param nonsense=1", {"nonsense", "sigma2"});
  expect_bad_input("render --method tokuyoshi --param sigma2=7", {"sigma2=7", "0 .. 1"});
  expect_bad_input("render --method tokuyoshi --param sigma2=abc", {"not a number"});
  expect_bad_input("render --method podee --param area=bogus", {"area=bogus", "not a choice", "exact|circle|lens"});
  expect_bad_input("render --method podee --param area=1.5", {"area=1.5", "exact|circle|lens"});
  expect_bad_input("render --method deng2022 --param rank=4.5", {"rank=4.5", "not an integer", "an integer 1 .. 64"});
  // Numbers are shown as written, not rounded to six digits.
  expect_bad_input("render --scene '" + write("angle.toml", TestScene::minimal().film(16, 16).toml() +
                                                    "\n[[light]]\ntype = \"spot\"\nposition = [0, 2, 0]\n"
                                                    "direction = [0, -1, 0]\nouter_angle = 360.0001\n").string() + "'",
                   {"outer_angle", "value 360.0001 is out of range"});
  expect_bad_input("render --scene '" + write("seed.toml", TestScene::minimal().film(16, 16).toml() +
                                                   "\n[[material]]\nname = \"s\"\ntype = \"microfacet\"\n"
                                                   "normal_map = { generator = \"bumps\", resolution = 16, seed = -1 }\n").string() + "'",
                   {"'seed'", "allowed: 0 .. 1073741824"});
  expect_bad_input("compare --spp 0", {"--spp 0", "1 .. 65536"});
  expect_bad_input("compare --spp lots", {"--spp=lots", "auto"});
  expect_bad_input("render --reference=many", {"--reference=many", "auto"});
  expect_bad_input("compare --spp auto --max-spp 10", {"--max-spp 10", "256 .. 65536"});
  expect_bad_input("compare --spp auto --noise-fraction 2", {"--noise-fraction", "(0, 1]"});
  expect_bad_input("render --width 100000", {"100000", "16384"});
  expect_bad_input("render --frame 999", {"--frame 999"});
  expect_bad_input("render --no-such-flag", {"no-such-flag"});
  // Sizes and frame counts on the command line obey the scene file's limits (issue 13).
  expect_bad_input("render --width 0", {"--width", "0", "1 to 16384"});
  expect_bad_input("render --width -64", {"--width", "-64", "1 to 16384"});
  expect_bad_input("render --height -7", {"--height", "-7", "1 to 16384"});
  expect_bad_input("animate --frames 0", {"--frames", "1 to 100000"});
  expect_bad_input("animate --frames -3", {"--frames", "-3"});
  expect_bad_input("animate --frames 100001", {"--frames", "100001", "1 to 100000"});
  expect_bad_input("render --reference-backend nope", {"nope", "raster"});
  expect_bad_input("compare --spp 4 --reference-backend path:deng2022", {"path:deng2022", "ground truth", "allowed: raster"});
  expect_bad_input("converge --backends raster --steps 4,1", {"--steps", "rising"});
  expect_bad_input("converge --backends 'raster,path:lean'", {"path:lean", "path:deng2022"});
  expect_bad_input("compare --spp 4 --methods 'conventional,podee{area=square}'",
                   {"'podee{area=square}'", "area=square", "exact|circle|lens"});
  for (const char* filter : {"gaussian:0", "gaussian:abc", "tent"})
    for (const char* command : {"render --reference=4", "compare --spp 4", "animate --spp 4 --frames 2"})
      expect_bad_input(std::string(command) + " --reference-filter " + filter,
                       {"--reference-filter", filter, "allowed: box, gaussian", "gaussian:S", "0.1 .. 4"});
}

TEST_F(Cli, OutputPathsAreCheckedBeforeAnythingIsWritten) {
  const std::string scene = " --scene '" + write("s.toml", kScene).string() + "' -q ";
  // An extension glintlab cannot write is bad input, not a directory named img.jpg.
  const auto jpg = scratch / "out" / "img.jpg";
  CliResult r = run_glintlab("render" + scene + "-o '" + jpg.string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("'.jpg'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch / "out")) << "nothing written";
  // A target that exists as a directory: exit 2, and the other file of the pair not written.
  fs::create_directories(scratch / "d" / "x.png");
  r = run_glintlab("render" + scene + "-o '" + (scratch / "d" / "x.png").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch / "d" / "x.exr"));
  // An output directory under a file.
  write("plain-file", "x");
  r = run_glintlab("compare" + scene + "--methods conventional --spp 4 -o '" + (scratch / "plain-file" / "sub").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("is a file, not a directory"), std::string::npos) << r.err;
  // Extensions it can write are accepted in any case.
  r = run_glintlab("render" + scene + "-o '" + (scratch / "up" / "x.PNG").string() + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(scratch / "up" / "x.exr"));
  EXPECT_TRUE(fs::is_regular_file(scratch / "up" / "x.png"));
}

TEST_F(Cli, ListingsWork) {
  EXPECT_EQ(run_glintlab("methods").code, 0);
  EXPECT_EQ(run_glintlab("scenes").code, 0);
  EXPECT_EQ(run_glintlab("scenes --print spheres").code, 0);
  EXPECT_EQ(run_glintlab("info").code, 0);
}

TEST_F(Cli, SameCommandWritesIdenticalFiles) {
  const fs::path scene = write("det.toml", kScene);
  const fs::path a = scratch / "det-a", b = scratch / "det-b";
  for (const auto& out : {a, b}) {
    // With a Gaussian pixel filter for the reference, which metrics.json records.
    // A method of each family (rendering on the GL is deterministic for all alike; compiling all
    // of them here would be half a minute of llvmpipe that other tests spend already).
    const CliResult r = run_glintlab(
        "compare --no-cache -q --spp 4 --reference-filter gaussian:0.5 --methods conventional,lean,podee,chermain2021,"
        "kneiphof2024,deng2022 --scene '" + scene.string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  for (const char* f : {"conventional.exr", "conventional.png", "reference.exr", "metrics.csv", "metrics.json"}) {
    ASSERT_TRUE(fs::exists(a / f)) << f;
    EXPECT_EQ(read_bytes(a / f), read_bytes(b / f)) << f;
  }
  EXPECT_NE(read_bytes(a / "metrics.json").find("\"reference_filter\": \"gaussian:0.5\""), std::string::npos);
}

TEST_F(Cli, AVariantAndItsMethodShareOneRunAndDifferInItsParameter) {
  // vlachos with its roughness floor's gain at the default and at 4, in one compare: one reference,
  // two rows, each with files of its own (a uniform parameter: one program for both).
  const fs::path out = scratch / "variants";
  const CliResult r = run_glintlab("compare -q --spp 4 --methods 'vlachos,vlachos{scale=4}' --scene '" +
                                   write("variants.toml", kScene).string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto metrics = nlohmann::json::parse(read_bytes(out / "metrics.json"));
  ASSERT_EQ(metrics["methods"].size(), 2u);
  EXPECT_EQ(metrics["methods"][0]["file"], "vlachos");
  EXPECT_EQ(metrics["methods"][1]["method"], "vlachos{scale=4}");
  EXPECT_EQ(metrics["methods"][1]["file"], "vlachos.scale=4");
  EXPECT_NE(read_bytes(out / "vlachos.scale=4.exr"), read_bytes(out / "vlachos.exr"))
      << "the parameter changed nothing";
  EXPECT_NE(metrics["methods"][0]["energy_ratio"], metrics["methods"][1]["energy_ratio"]);
  EXPECT_NE(read_bytes(out / "metrics.csv").find("\nvlachos{scale=4},"), std::string::npos);
  // The report shows the variant by its name, with its files.
  const fs::path report = scratch / "report";
  ASSERT_EQ(run_glintlab("report -o '" + report.string() + "' '" + out.string() + "'").code, 0);
  EXPECT_TRUE(fs::is_regular_file(report / "assets" / "variants" / "vlachos.scale=4-error.png"));
}

TEST_F(Cli, ReferenceCacheIsReused) {
  const fs::path scene = write("cache.toml", kScene);
  const auto render = [&](const std::string& out) {
    return run_glintlab("render -q --reference=16 --scene '" + scene.string() + "' -o '" + (scratch / out).string() + "'");
  };
  ASSERT_EQ(render("first").code, 0);
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(cache())) entries.push_back(e.path());
  ASSERT_EQ(entries.size(), 2u);  // the EXR and its passes' JSON
  const fs::path exr = entries[0].extension() == ".exr" ? entries[0] : entries[1];
  const fs::path json = fs::path(exr).replace_extension(".json");
  const nlohmann::json passes = nlohmann::json::parse(read_bytes(json));
  // Rewrites the entry's EXR from these images and its JSON from `meta`, with the EXR's checksum.
  const auto store_entry = [&](const glintlab::Image& mean, const glintlab::Image& rest, nlohmann::json meta) {
    glintlab::write_exr(exr, {{"", &mean}, {"specular", &rest}, {"standard_error", &rest}, {"even_passes", &rest},
                              {"odd_passes", &rest}});
    const std::string bytes = read_bytes(exr);
    glintlab::Hasher h;
    h.bytes(bytes.data(), bytes.size());
    meta["exr_checksum"] = h.digest();
    std::ofstream(json) << meta.dump();
  };
  // Replace the cached mean by an image no render gives: a run that reads the cache writes it
  // as its reference, a run that renders again would not.
  const glintlab::Image marker(16, 16, glm::vec3(0.25f, 0.5f, 0.75f));
  store_entry(marker, glintlab::read_exr(exr, "specular"), passes);
  ASSERT_EQ(render("second").code, 0);
  EXPECT_TRUE(glintlab::read_exr(scratch / "second" / "reference.exr").pixels() == marker.pixels())
      << "the second run did not take its reference from the cache";
  // Damaged, foreign or impossible entries are reported, ignored and replaced: the image is
  // rendered again, equal to the first.
  const auto expect_rebuilt = [&](const char* problem) {
    const CliResult again = render("again");
    ASSERT_EQ(again.code, 0) << again.err;
    EXPECT_NE(again.err.find("ignoring the cache entry"), std::string::npos) << again.err;
    EXPECT_NE(again.err.find(problem), std::string::npos) << again.err;
    EXPECT_EQ(read_bytes(scratch / "first" / "reference.exr"), read_bytes(scratch / "again" / "reference.exr"));
  };
  fs::resize_file(exr, 100);
  expect_rebuilt("checksum");
  const glintlab::Image small(8, 8, glm::vec3(0.5f));
  store_entry(small, small, passes);
  expect_rebuilt("not 16x16");
  nlohmann::json no_specular_passes = passes;
  no_specular_passes["pass_luminance_specular"] = nlohmann::json::array();
  store_entry(marker, marker, no_specular_passes);
  expect_rebuilt("pass counts disagree");
  glintlab::Image nan_pixel = marker;
  nan_pixel.pixels()[5].y = std::nanf("");
  store_entry(nan_pixel, marker, passes);
  expect_rebuilt("NaN");
  EXPECT_GT(fs::file_size(exr), 100u);
}

TEST_F(Cli, ACopiedBuiltinSceneFileRendersLikeTheBuiltin) {
  // What a user does: copy scenes/NAME.toml (= `glintlab scenes --print NAME`) and load it by path.
  const fs::path copy = scratch / "my-mirror-bumps.toml";
  fs::copy_file(GLINTLAB_SCENES_DIR "/mirror-bumps.toml", copy);
  for (const auto& [scene, out] : {std::pair<std::string, std::string>{"builtin:mirror-bumps", "builtin.exr"},
                                   {copy.string(), "copy.exr"}}) {
    const CliResult r = run_glintlab("render -q --method lean --width 64 --height 36 --scene '" + scene + "' -o '" +
                                     (scratch / out).string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  EXPECT_EQ(read_bytes(scratch / "builtin.exr"), read_bytes(scratch / "copy.exr"));
}

TEST_F(Cli, AutoReferenceReachesItsTargetOrItsCapAndReportsItsNoise) {
  const fs::path scene =
      write("auto.toml", TestScene::minimal().film(24, 16).sphere_light({1, 2, 2}, 0.3, 20).toml());
  int spp = 0;
  for (const auto& [backend, cap] : {std::pair<std::string, int>{"raster", 256}, {"raster", 1024}, {"path", 256}}) {
    const fs::path out = scratch / ("auto-" + backend + "-" + std::to_string(cap));
    const CliResult r = run_glintlab("compare -q --spp auto --max-spp " + std::to_string(cap) + " --reference-backend " +
                                     backend + " --methods conventional,toksvig,kaplanyan-ggx --scene '" +
                                     scene.string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string json = read_bytes(out / "metrics.json");
    auto number = [&](const std::string& key) {
      const auto at = json.find("\"" + key + "\": ");
      EXPECT_NE(at, std::string::npos) << key;
      return at == std::string::npos ? -1.0 : std::stod(json.substr(at + key.size() + 4));
    };
    EXPECT_NE(json.find("\"reference_backend\": \"" + backend + "\""), std::string::npos) << json;
    EXPECT_EQ(number("reference_max_depth"), 1);
    const double reached = number("reference_spp"), noise = number("reference_noise_rmse");
    const double target = number("reference_noise_target");
    EXPECT_GE(reached, 256);
    EXPECT_LE(reached, cap);
    EXPECT_GT(noise, 0.0);
    EXPECT_TRUE(noise <= target || reached == cap) << noise << " > " << target << " at " << reached;
    if (backend == "raster") {  // continued from the cache: a larger cap never gives fewer samples
      EXPECT_GE(reached, spp);
      spp = static_cast<int>(reached);
    }
    EXPECT_NE(read_bytes(out / "metrics.csv").find("reference_noise_rmse"), std::string::npos);
  }
}

TEST_F(Cli, AnimateWritesDecodableMp4sWithEveryFrame) {
  // ffmpeg is one of the set-up's packages (tools/install-deps.sh); without it animate writes PNGs.
  if (std::system("command -v ffprobe >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg is not installed";
  const auto out = scratch / "anim";
  const std::string scene = TestScene::minimal().film(18, 14).raw("[camera.path]\ntype = \"orbit\"\nframes = 5\n").toml();
  const CliResult r = run_glintlab("animate --scene '" + write("orbit.toml", scene).string() +
                                   "' --methods conventional --spp 4 -q -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* video : {"conventional.mp4", "reference.mp4"}) {
    const auto mp4 = out / video;
    ASSERT_TRUE(fs::is_regular_file(mp4)) << video;
    // Decoded to the end (-count_frames): its frame count and size (odd sizes padded to even).
    const auto probe = scratch / "probe.txt";
    const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=nb_read_frames,width,height -of csv=p=0 '" + mp4.string() + "' > '" +
                            probe.string() + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << video << " does not decode";
    EXPECT_EQ(read_bytes(probe), "18,14,5\n") << video;
  }
}

TEST_F(Cli, HostileMeshExitsWith2AndWritesNothing) {
  // A face whose normal index is past the `vn` lines crashed load_mesh_file (issue 13).
  write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n");
  const fs::path scene = write("hostile.toml", TestScene::minimal().film(16, 16).shape("mesh", "m", {{"file", "bad.obj"}}).toml());
  expect_bad_input("render --scene '" + scene.string() + "'", {"bad.obj:5", "normal index 2", "allowed: 1 to 1"});
}

TEST_F(Cli, ARunTooLargeForTheMemoryIsExit2BeforeRendering) {
  // 3 spheres compared at 4096x4096 ended in std::bad_alloc (issue 13): the memory a run needs is
  // estimated before the GPU work; GLINTLAB_MEMORY_MIB stands in for a small machine.
  const fs::path scene = write("three.toml", TestScene::minimal().film(16, 16).sphere("m").sphere("m").toml());
  env = "GLINTLAB_MEMORY_MIB=1024";
  expect_bad_input("compare --methods all --scene '" + scene.string() + "' --width 4096 --height 4096",
                   {"film 4096x4096 with", "methods and a reference needs", "available: 1.00 GiB", "--width/--height"});
  expect_bad_input("render --scene '" + scene.string() + "' --width 4096 --height 4096", {"film 4096x4096 with 1 method needs"});
  // A small film fits the same budget.
  const CliResult fits = run_glintlab("render --scene '" + scene.string() + "' -o '" + (scratch / "ok").string() + "'");
  EXPECT_EQ(fits.code, 0) << fits.err;
  // A generator's map is refused before it is built (an 8192^2 flakes map took 13.6 s to build).
  const fs::path flakes = write("flakes.toml", kScene + "\n[[material]]\nname = \"f\"\ntype = \"microfacet\"\n"
                                               "normal_map = { generator = \"flakes\", resolution = 8192 }\n");
  expect_bad_input("render --scene '" + flakes.string() + "'",
                   {"flakes.toml:", "'resolution'", "8192 x 8192 map needs", "available: 1.00 GiB"});
  env = "GLINTLAB_MEMORY_MIB=lots";
  expect_bad_input("render --scene '" + scene.string() + "'", {"GLINTLAB_MEMORY_MIB=lots", "allowed"});
}

TEST_F(Cli, BadEnvironmentMapsExitWith2AndWriteNothing) {
  // An environment light's map: missing, not lat-long (2:1), a NaN texel; each names the file.
  const auto scene_with_map = [&](const std::string& name, const std::string& map) {
    return write(name, TestScene().film(16, 16).material("m").sphere("m").light("environment", {{"file", map}}).toml());
  };
  glintlab::Image square(16, 16, glm::vec3(1.0f)), with_nan(16, 8, glm::vec3(1.0f));
  with_nan.at(3, 2).g = std::nanf("");
  glintlab::write_exr(scratch / "square.exr", {{"", &square}});
  glintlab::write_exr(scratch / "nan.exr", {{"", &with_nan}});
  expect_bad_input("render --scene '" + scene_with_map("missing.toml", "missing.exr").string() + "'",
                   {"missing.toml", "missing.exr"});
  expect_bad_input("render --scene '" + scene_with_map("square.toml", "square.exr").string() + "'",
                   {"square.exr", "16 x 16", "twice as wide"});
  expect_bad_input("render --scene '" + scene_with_map("nan.toml", "nan.exr").string() + "'", {"nan.exr", "3, 2"});
  // One light needs one source, and a scene at most one environment.
  expect_bad_input("render --scene '" +
                       write("two-sources.toml", TestScene().film(16, 16).material("m").sphere("m")
                                                     .light("environment", {{"radiance", 1.0}, {"generator", "studio"}})
                                                     .toml())
                           .string() +
                       "'",
                   {"two-sources.toml", "exactly one of"});
  expect_bad_input("render --scene '" +
                       write("two-environments.toml", TestScene().film(16, 16).material("m").sphere("m")
                                                          .light("environment", {{"radiance", 1.0}})
                                                          .light("environment", {{"radiance", 2.0}})
                                                          .toml())
                           .string() +
                       "'",
                   {"two-environments.toml", "at most one"});
}

TEST_F(Cli, EnvironmentFitWritesTheLobesAsAMapWithTheMapsPower) {
  // `glintlab environment-fit` (and `prefilter`): a scene without what it reads is bad input naming
  // the scene; with
  // one, -o writes the last count's fit as a map of the environment's size and power (the fit keeps it).
  const fs::path bare = write("bare.toml", TestScene().film(16, 16).material("m").sphere("m").point_light({0, 2, 0}).toml());
  expect_bad_input("environment-fit --scene '" + bare.string() + "'", {"bare.toml", "no environment"});
  expect_bad_input("prefilter --scene '" + bare.string() + "'", {"bare.toml", "no normal-map-glints"});
  glintlab::Image map(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) map.at(x, y) = glm::vec3(1.0f + 0.05f * x, 0.5f, y < 8 ? 4.0f : 0.25f);
  glintlab::write_exr(scratch / "sky.exr", {{"", &map}});
  const fs::path scene = write("sky.toml", TestScene().film(16, 16).material("m").sphere("m")
                                               .light("environment", {{"file", "sky.exr"}}).toml());
  const fs::path out = scratch / "lobes.exr";
  const CliResult r = run_glintlab("environment-fit --scene '" + scene.string() + "' --lobes 4,24 -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const glintlab::Image fitted = glintlab::read_exr(out);
  ASSERT_EQ(fitted.width(), 64);
  ASSERT_EQ(fitted.height(), 32);
  glm::dvec3 power(0.0), fitted_power(0.0);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      power += glm::dvec3(map.at(x, y)) * glintlab::environment_row_solid_angle(y, 32);
      fitted_power += glm::dvec3(fitted.at(x, y)) * glintlab::environment_row_solid_angle(y, 32);
    }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fitted_power[c] / power[c], 1.0, 0.01) << "channel " << c;  // texel centres, not integrals
}

TEST_F(Cli, BenchWithoutWarmUpTimesItsFirstFrameRight) {
  // The GPU works inside the wall-clock interval of each frame, so its time cannot exceed it; the
  // first timed frame of a run used to report the time since llvmpipe's clock's epoch (7e6 ms).
  const fs::path out = scratch / "bench";
  const CliResult r = run_glintlab("bench -q --scene '" + write("s.toml", kScene).string() +
                                   "' --methods conventional --bench-frames 1 --warmup 0 -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json bench = nlohmann::json::parse(read_bytes(out / "bench.json"));
  for (const auto& m : bench.at("methods"))
    EXPECT_LE(m.at("gpu_ms_median").get<double>(), m.at("wall_ms_median").get<double>() + 1.0) << m.dump();
}

TEST_F(Cli, MaxDepthOutsideItsRangeOrWithoutThePathBackendIsBadInput) {
  const std::string scene = " --scene '" + write("s.toml", kScene).string() + "'";
  expect_bad_input("render" + scene + " --reference=4 --reference-backend path --max-depth 0", {"--max-depth 0", "1 .. 64"});
  expect_bad_input("render" + scene + " --reference=4 --reference-backend path --max-depth 65", {"--max-depth 65", "1 .. 64"});
  expect_bad_input("render" + scene + " --reference=4 --max-depth 2",
                   {"--max-depth 2 with --reference-backend raster", "direct light only", "--reference-backend path"});
}
