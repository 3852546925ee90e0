// glintlab view as a person uses it, on a virtual display (Xvfb): a scripted sequence switches
// the method, changes a parameter, moves to another frame and takes a screenshot, which must be
// the very files `glintlab render` writes for that method and frame. Skipped, saying why, where
// Xvfb cannot start.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/image_io.hpp"
#include "app/cli_fixture.hpp"  // read_bytes
#include "scratch_directory.hpp"

namespace fs = std::filesystem;

namespace glintlab {
namespace {

struct CommandResult {
  int code;
  std::string err;
};

using test::read_bytes;

class View : public ::testing::Test {
 protected:
  /// Runs `command` (a shell line) with this test's reference cache; stderr comes back.
  CommandResult run(const std::string& command) const {
    const fs::path err = dir / "stderr.txt";
    const std::string line = "GLINTLAB_CACHE_DIR='" + (dir / "cache").string() + "' " + command + " >'" +
                             (dir / "stdout.txt").string() + "' 2>'" + err.string() + "'";
    const int status = std::system(line.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_bytes(err)};
  }
  std::string glintlab(const std::string& args) const { return "'" GLINTLAB_BINARY "' " + args; }
  /// glintlab under a virtual display of its own.
  std::string under_xvfb(const std::string& args) const {
    return "xvfb-run -a -s '-screen 0 1280x800x24' " + glintlab(args);
  }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  /// Skips the test, with the reason, when no virtual display can be started here.
  void require_xvfb() const {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "xvfb-run is not installed (Debian package xvfb): the viewer needs a display to test";
    if (const CommandResult r = run("xvfb-run -a -s '-screen 0 640x480x24' true"); r.code != 0)
      GTEST_SKIP() << "Xvfb cannot start here (exit " << r.code << "): " << r.err;
  }
  test::ScratchDirectory dir;
};

const std::string kScene = "--scene builtin:spheres --width 64 --height 36";

void expect_same_image(const fs::path& a, const fs::path& b, const std::string& layer) {
  const Image x = read_exr(a, layer), y = read_exr(b, layer);
  ASSERT_EQ(x.width(), y.width());
  ASSERT_EQ(x.height(), y.height());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < x.pixel_count(); ++i) differ += x.pixels()[i] != y.pixels()[i];
  EXPECT_EQ(differ, 0u) << a << " vs " << b << ", layer '" << layer << "'";
}

bool same_pixels(const fs::path& a, const fs::path& b) {
  const Image x = read_exr(a), y = read_exr(b);
  return x.pixels() == y.pixels();
}

TEST_F(View, ScriptedScreenshotIsTheHeadlessRenderOfTheSameMethodAndFrame) {
  require_xvfb();
  const fs::path shot = dir / "view" / "shot.exr", window = dir / "window.png";
  const fs::path script = write("script.txt",
                                "method vlachos\n"
                                "param scale=3\n"
                                "frame 2\n"
                                "screenshot " + shot.string() + "\n"
                                "mode split\n"
                                "compare conventional\n"
                                "error-overlay on 0.5\n"
                                "magnify 30 18 8\n"
                                "window-screenshot " + window.string() + "\n"
                                "mode flip\n"
                                "flip\n"
                                "orbit 20 5\n"
                                "quit\n");
  const CommandResult view = run(under_xvfb("view " + kScene + " --script '" + script.string() + "'"));
  ASSERT_EQ(view.code, 0) << view.err;

  const fs::path headless = dir / "headless" / "vlachos.exr";
  const CommandResult render = run(glintlab("render " + kScene + " --method vlachos --param scale=3 --frame 2 -o '" +
                                  headless.string() + "'"));
  ASSERT_EQ(render.code, 0) << render.err;
  expect_same_image(shot, headless, "");
  expect_same_image(shot, headless, "specular");
  EXPECT_EQ(read_bytes(shot), read_bytes(headless)) << "the EXR files differ";
  EXPECT_EQ(read_bytes(fs::path(shot).replace_extension(".png")), read_bytes(fs::path(headless).replace_extension(".png")));

  // The parameter and the frame took effect: the default parameter, or frame 0, render otherwise.
  const fs::path default_scale = dir / "other" / "default.exr", first_frame = dir / "other" / "frame0.exr";
  ASSERT_EQ(run(glintlab("render " + kScene + " --method vlachos --frame 2 -o '" + default_scale.string() + "'")).code, 0);
  ASSERT_EQ(run(glintlab("render " + kScene + " --method vlachos --param scale=3 -o '" + first_frame.string() + "'")).code, 0);
  EXPECT_FALSE(same_pixels(shot, default_scale)) << "the parameter change did not reach the screenshot";
  EXPECT_FALSE(same_pixels(shot, first_frame)) << "the frame change did not reach the screenshot";

  // The sidecar says how to write the same files headless.
  const std::string json = read_bytes(fs::path(shot).replace_extension(".json"));
  EXPECT_NE(json.find("glintlab render --scene builtin:spheres --method vlachos --param scale=3 --frame 2"), std::string::npos)
      << json;

  // The window as shown (controls, split picture, error map, magnifier): the window's size, not blank.
  const Image w = read_ldr_image(window);
  EXPECT_EQ(w.width(), 1280);
  EXPECT_EQ(w.height(), 800);
  double sum = 0, sum2 = 0;
  for (const auto& p : w.pixels()) sum += p.g, sum2 += p.g * p.g;
  const double n = static_cast<double>(w.pixel_count()), variance = sum2 / n - (sum / n) * (sum / n);
  EXPECT_GT(variance, 1e-3) << "the window screenshot is blank";
}

TEST_F(View, EveryCommandRunsAndDisplaySettingsChangeOnlyThePng) {
  require_xvfb();
  const fs::path shot = dir / "shot.exr", moved = dir / "moved.exr";
  const fs::path script = write("script.txt",
                                "compare lean\n"
                                "compare-param area_lights=representative-point\n"
                                "mode flip\nflip\nflip\nmode single\n"
                                "param scale=2\nreset-params\n"
                                "play\nwait 2\npause\nnext\nprevious\n"
                                "continuous on\nwait 1\ncontinuous off\n"
                                "magnify 10 10 4\nmagnify off\n"
                                "frame 1\nexposure 1.5\nbloom 0.5\n"
                                "screenshot " + shot.string() + "\n"
                                "orbit 30 10\ndolly 0.8\nfly 0.1 0 0.2\nlook 5 -3\n"
                                "screenshot " + moved.string() + "\n"
                                "path\nquit\n");
  const CommandResult view = run(under_xvfb("view " + kScene + " --method vlachos --script '" + script.string() + "'"));
  ASSERT_EQ(view.code, 0) << view.err;
  const fs::path headless = dir / "headless.exr";
  ASSERT_EQ(run(glintlab("render " + kScene + " --method vlachos --frame 1 -o '" + headless.string() + "'")).code, 0);
  // Exposure and bloom are display settings: the EXR is the render's, the PNG is not.
  EXPECT_EQ(read_bytes(shot), read_bytes(headless));
  EXPECT_NE(read_bytes(fs::path(shot).replace_extension(".png")), read_bytes(fs::path(headless).replace_extension(".png")));
  const std::string json = read_bytes(fs::path(shot).replace_extension(".json"));
  EXPECT_NE(json.find("\"exposure\": 1.5"), std::string::npos) << json;
  EXPECT_EQ(json.find("render_command"), std::string::npos) << "a command that writes another PNG: " << json;
  // The free camera moved the picture, and says it is off the path.
  EXPECT_FALSE(same_pixels(moved, shot));
  EXPECT_NE(read_bytes(fs::path(moved).replace_extension(".json")).find("\"on_path\": false"), std::string::npos);
}

TEST_F(View, ABadScriptIsExit2BeforeAnyWindowOpens) {
  const fs::path script = write("bad.txt", "method vlachos\nframe two\n");
  // No display at all: the script is read, and refused, first.
  const CommandResult r = run("env -u DISPLAY " + glintlab("view " + kScene + " --script '" + script.string() + "'"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.txt:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'two' is not a number"), std::string::npos) << r.err;
}

TEST_F(View, WithoutADisplayTheErrorSaysHowToGetOne) {
  const CommandResult r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + glintlab("view " + kScene));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
}

TEST_F(View, AnUnknownMethodOrFrameIsExit2) {
  require_xvfb();
  const fs::path script = write("s.txt", "method no-such-method\n");
  const CommandResult r = run(under_xvfb("view " + kScene + " --script '" + script.string() + "'"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("s.txt:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no-such-method"), std::string::npos) << r.err;
  // A magnifier pinned outside the film is known only once the film is: refused at its line.
  const fs::path outside = write("outside.txt", "magnify 100000 3 8\n");
  const CommandResult magnify = run(under_xvfb("view " + kScene + " --script '" + outside.string() + "'"));
  EXPECT_EQ(magnify.code, 2) << magnify.err;
  EXPECT_NE(magnify.err.find("outside.txt:1: magnify 100000 3: outside the film"), std::string::npos) << magnify.err;
  const CommandResult frame = run(under_xvfb("view " + kScene + " --method lean --frame 999"));
  EXPECT_EQ(frame.code, 2) << frame.err;
  EXPECT_NE(frame.err.find("--frame 999: allowed: 0 .. "), std::string::npos) << frame.err;
}

}  // namespace
}  // namespace glintlab
