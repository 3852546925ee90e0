// Special files where glintlab expects regular ones (src/core/file_access.hpp): every read of a
// FIFO, a device or a directory is exit 2 naming it, at once (never a hang, never reading
// /dev/zero until memory runs out), and no write replaces what is not a regular file. The FIFOs
// are made in each test's own scratch directory.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "app/cli_fixture.hpp"
#include "test_scenes.hpp"

namespace fs = std::filesystem;
using glintlab::test::Cli;
using glintlab::test::CliResult;
using glintlab::test::TestScene;

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// A scene whose one material reads its normal map from `file`.
std::string scene_with_normal_map(const fs::path& file) {
  return TestScene::minimal().film(16, 16).toml() + "\n[[material]]\nname = \"bumpy\"\ntype = \"microfacet\"\n" +
         "normal_map = { file = \"" + file.string() + "\" }\n";
}

}  // namespace

TEST_F(Cli, ReadsOfSpecialFilesAreExit2AtOnce) {
  const fs::path fifo_png = scratch / "fifo.png", fifo_exr = scratch / "fifo.exr", fifo_toml = scratch / "fifo.toml";
  for (const auto& f : {fifo_png, fifo_exr, fifo_toml}) ASSERT_EQ(::mkfifo(f.c_str(), 0600), 0);
  fs::create_directories(scratch / "folder.png");
  // Normal maps: a FIFO (by either extension), a directory, a device.
  for (const fs::path& map : {fifo_png, fifo_exr, scratch / "folder.png", fs::path("/dev/zero")}) {
    if (!fs::exists(map)) continue;
    const fs::path scene = write("bumpy.toml", scene_with_normal_map(map));
    expect_bad_input("render --scene " + quoted(scene), {map.string().c_str(), "allowed: a regular file"});
  }
  // An environment light's map.
  const fs::path lit = write("environment.toml", TestScene::minimal().film(16, 16).toml() +
                                                     "\n[[light]]\ntype = \"environment\"\nfile = \"" +
                                                     fifo_exr.string() + "\"\n");
  expect_bad_input("render --scene " + quoted(lit), {fifo_exr.string().c_str(), "FIFO"});
  expect_bad_input("render --scene " + quoted(fifo_toml), {"fifo.toml", "FIFO"});
  expect_bad_input("render --scene " + quoted(scratch / "folder.png"), {"folder.png", "directory"});
  // Viewer scripts are read before any window opens.
  for (const fs::path& script : {fifo_toml, scratch / "folder.png", fs::path("/dev/zero")}) {
    if (!fs::exists(script)) continue;
    const CliResult r = run_glintlab("view --script " + quoted(script));
    EXPECT_EQ(r.code, 2) << script << "\n" << r.err;
    EXPECT_NE(r.err.find("--script " + script.string()), std::string::npos) << r.err;
  }
}

TEST_F(Cli, ADeeplyNestedSceneFileIsExit2NotACrash) {
  // 50,000 levels overflowed toml++'s recursive parser's stack (SIGSEGV).
  std::string header = "[a";
  for (int i = 0; i < 50000; ++i) header += ".a";
  expect_bad_input("render --scene " + quoted(write("deep.toml", header + "]\n")), {"deep.toml:1", "at most 64"});
  std::string dotted = "a";
  for (int i = 0; i < 100; ++i) dotted += ".a";
  expect_bad_input("render --scene " + quoted(write("dotted.toml", "x = 1\n" + dotted + " = 1\n")), {"dotted.toml:2"});
  // Dots inside strings and numbers are not levels.
  const std::string dots_in_values = TestScene::minimal().film(16, 16).toml() + "# " + dotted + "\n";
  const CliResult fine = run_glintlab("render -q --scene " + quoted(write("fine.toml", dots_in_values)) + " -o " +
                                      quoted(scratch / "fine.png"));
  EXPECT_EQ(fine.code, 0) << fine.err;
}

TEST_F(Cli, OutputsNeverReplaceWhatIsNotARegularFile) {
  const std::string scene_file = " --scene " + quoted(write("s.toml", TestScene::minimal().film(16, 16).toml()));
  const std::string scene = scene_file + " -q ";
  // prefilter -o: refused before the precompute (the scene is read after the check).
  if (fs::exists("/dev/full")) {
    const CliResult r = run_glintlab("prefilter" + scene_file + " -o /dev/full");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("character device"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_character_file("/dev/full")) << "/dev/full was replaced";
  }
  write("plain-file", "x");
  for (const auto& [target, fragment] : {std::pair<std::string, const char*>{".", "names a directory"},
                                         {(scratch / "plain-file" / "r.json").string(), "not a directory"},
                                         {scratch.path().string(), "is a directory"}}) {
    const CliResult r = run_glintlab("prefilter --scene builtin:no-such-scene -o " + quoted(fs::path(target)));
    EXPECT_EQ(r.code, 2) << target << "\n" << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  }
  // A FIFO or a link where render would write an image: left as it was.
  const fs::path fifo = scratch / "frame.png", elsewhere = scratch / "elsewhere.exr", link = scratch / "frame.exr";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  CliResult r = run_glintlab("render" + scene + "-o " + quoted(fifo));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("FIFO"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  fs::remove(fifo);
  write("elsewhere.exr", "keep me");
  fs::create_symlink(elsewhere, link);
  r = run_glintlab("render" + scene + "-o " + quoted(scratch / "frame.png"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("symbolic link"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_FALSE(fs::exists(scratch / "frame.png")) << "the other file of the pair was written";
  // compare publishes nothing when one of its files' places holds a FIFO.
  const fs::path out = scratch / "compare";
  fs::create_directories(out);
  ASSERT_EQ(::mkfifo((out / "metrics.json").c_str(), 0600), 0);
  r = run_glintlab("compare" + scene + "--methods conventional --spp 4 -o " + quoted(out));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("metrics.json"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_fifo(out / "metrics.json"));
  EXPECT_FALSE(fs::exists(out / "reference.png")) << "a partial output was published";
}
