// The CLI end to end: every class of bad input gets exit code 2, a message naming what is wrong,
// and no output file; the same command writes identical files twice.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_scenes.hpp"

namespace fs = std::filesystem;

namespace {

struct CliResult {
  int code;
  std::string err;
};

fs::path scratch() {
  static const fs::path dir = fs::temp_directory_path() / ("glintlab-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

CliResult run_glintlab(const std::string& args) {
  const fs::path err = scratch() / "stderr.txt";
  const std::string cmd = std::string("GLINTLAB_CACHE_DIR='") + (scratch() / "cache").string() + "' '" GLINTLAB_BINARY "' " +
                          args + " >/dev/null 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, s.str()};
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p;
}

const std::string kScene = "[film]\nwidth = 16\nheight = 16\n" + glintlab::test::kMinimalScene;

void expect_bad_input(const std::string& args, std::initializer_list<const char*> fragments) {
  const fs::path out = scratch() / "out-should-not-exist";
  fs::remove_all(out);
  const CliResult r = run_glintlab(args + " -o '" + out.string() + "'");
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  for (const char* f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' not in: " << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(Cli, BadInputClassesExitWith2AndWriteNothing) {
  const auto missing = (scratch() / "missing.toml").string();
  expect_bad_input("render --scene '" + missing + "'", {"missing.toml", "does not exist"});
  expect_bad_input("render --scene '" + write("malformed.toml", "[film\n").string() + "'", {"malformed.toml:1", "malformed"});
  expect_bad_input("render --scene '" + write("unknown.toml", kScene + "[camera]\nfoo = 1\n").string() + "'", {"'foo'", "not a known key"});
  expect_bad_input("render --scene '" + write("type.toml", "[film]\nwidth = 1.5\n" + glintlab::test::kMinimalScene).string() + "'", {"width", "not an integer"});
  expect_bad_input("render --scene '" + write("range.toml", kScene + "[[light]]\ntype = \"sphere\"\nposition = [0,0,0]\nradius = -1\n").string() + "'",
                   {"radius", "out of range"});
  expect_bad_input("render --scene '" + write("mesh.toml", kScene + "[[shape]]\ntype = \"mesh\"\nmaterial = \"m\"\nfile = \"nope.obj\"\n").string() + "'",
                   {"nope.obj"});
  expect_bad_input("render --scene builtin:nothing", {"builtin:nothing", "spheres"});
  expect_bad_input("render --method magic", {"unknown method 'magic'", "conventional"});
  expect_bad_input("render --method tokuyoshi --param nonsense=1", {"nonsense", "sigma2"});
  expect_bad_input("render --method tokuyoshi --param sigma2=7", {"sigma2=7", "0 .. 1"});
  expect_bad_input("render --method tokuyoshi --param sigma2=abc", {"not a number"});
  expect_bad_input("render --method podee --param area=bogus", {"area=bogus", "not a choice", "exact|circle|lens"});
  expect_bad_input("render --method podee --param area=1.5", {"area=1.5", "exact|circle|lens"});
  expect_bad_input("compare --spp 0", {"--spp 0", "1 .. 65536"});
  expect_bad_input("compare --spp lots", {"--spp=lots", "auto"});
  expect_bad_input("render --reference=many", {"--reference=many", "auto"});
  expect_bad_input("compare --spp auto --max-spp 10", {"--max-spp 10", "256 .. 65536"});
  expect_bad_input("compare --spp auto --noise-fraction 2", {"--noise-fraction", "(0, 1]"});
  expect_bad_input("render --width 100000", {"100000", "16384"});
  expect_bad_input("render --frame 999", {"--frame 999"});
  expect_bad_input("render --no-such-flag", {"no-such-flag"});
}

TEST(Cli, ListingsWork) {
  EXPECT_EQ(run_glintlab("methods").code, 0);
  EXPECT_EQ(run_glintlab("scenes").code, 0);
  EXPECT_EQ(run_glintlab("scenes --print spheres").code, 0);
  EXPECT_EQ(run_glintlab("info").code, 0);
}

TEST(Cli, SameCommandWritesIdenticalFiles) {
  const fs::path scene = write("det.toml", kScene);
  const fs::path a = scratch() / "det-a", b = scratch() / "det-b";
  for (const auto& out : {a, b}) {
    const CliResult r = run_glintlab("compare --no-cache -q --spp 4 --scene '" + scene.string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  for (const char* f : {"conventional.exr", "conventional.png", "reference.exr", "metrics.csv", "metrics.json"}) {
    ASSERT_TRUE(fs::exists(a / f)) << f;
    EXPECT_EQ(read_bytes(a / f), read_bytes(b / f)) << f;
  }
}

TEST(Cli, ReferenceCacheIsReused) {
  const fs::path scene = write("cache.toml", kScene);
  fs::remove_all(scratch() / "cache");
  ASSERT_EQ(run_glintlab("render -q --reference=16 --scene '" + scene.string() + "' -o '" + (scratch() / "c1").string() + "'").code, 0);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(scratch() / "cache")) ++entries;
  EXPECT_EQ(entries, 2);  // the EXR and its passes' JSON
  ASSERT_EQ(run_glintlab("render -q --reference=16 --scene '" + scene.string() + "' -o '" + (scratch() / "c2").string() + "'").code, 0);
  EXPECT_EQ(read_bytes(scratch() / "c1" / "reference.exr"), read_bytes(scratch() / "c2" / "reference.exr"));
}

TEST(Cli, AutoReferenceReachesItsTargetOrItsCapAndReportsItsNoise) {
  const fs::path scene = write("auto.toml", "[film]\nwidth = 24\nheight = 16\n" + glintlab::test::kMinimalScene +
                                                "[[light]]\ntype = \"sphere\"\nposition = [1, 2, 2]\nradius = 0.3\n"
                                                "radiance = 20\n");
  fs::remove_all(scratch() / "cache");
  int spp = 0;
  for (const int cap : {256, 1024}) {
    const fs::path out = scratch() / ("auto-" + std::to_string(cap));
    const CliResult r = run_glintlab("compare -q --spp auto --max-spp " + std::to_string(cap) +
                                     " --methods conventional,toksvig,kaplanyan-ggx --scene '" + scene.string() +
                                     "' -o '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string json = read_bytes(out / "metrics.json");
    auto number = [&](const std::string& key) {
      const auto at = json.find("\"" + key + "\": ");
      EXPECT_NE(at, std::string::npos) << key;
      return at == std::string::npos ? -1.0 : std::stod(json.substr(at + key.size() + 4));
    };
    const double reached = number("reference_spp"), noise = number("reference_noise_rmse");
    const double target = number("reference_noise_target");
    EXPECT_GE(reached, 256);
    EXPECT_LE(reached, cap);
    EXPECT_GT(noise, 0.0);
    EXPECT_TRUE(noise <= target || reached == cap) << noise << " > " << target << " at " << reached;
    // Continued from the cache: a larger cap never gives fewer samples.
    EXPECT_GE(reached, spp);
    spp = static_cast<int>(reached);
    EXPECT_NE(read_bytes(out / "metrics.csv").find("reference_noise_rmse"), std::string::npos);
  }
}
