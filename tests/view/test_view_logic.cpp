// The viewer's parts that need no window: the free camera's moves, the picture's composition and
// the script reader's errors.
#include <gtest/gtest.h>

#include <fstream>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "scratch_directory.hpp"
#include "view/camera_controls.hpp"
#include "view/display_compose.hpp"
#include "view/view_script.hpp"

namespace glintlab {
namespace {

Camera test_camera() {
  Camera c;
  c.position = {1.0f, 2.0f, 5.0f};
  c.target = {0.0f, 0.5f, 0.0f};
  return c;
}

float distance(const Camera& c) { return glm::length(c.position - c.target); }

TEST(CameraControls, OrbitKeepsTheTargetAndItsDistance) {
  const Camera c = test_camera();
  const Camera o = orbit_camera(c, 37.0f, 12.0f);
  EXPECT_EQ(o.target, c.target);
  EXPECT_NEAR(distance(o), distance(c), 1e-5f);
  EXPECT_GT(glm::length(o.position - c.position), 0.1f);
  // A full turn about the up axis comes back.
  const Camera full = orbit_camera(c, 360.0f, 0.0f);
  EXPECT_NEAR(glm::length(full.position - c.position), 0.0f, 1e-4f);
  // Yaw then its inverse comes back too.
  const Camera back = orbit_camera(orbit_camera(c, 50.0f, 0.0f), -50.0f, 0.0f);
  EXPECT_NEAR(glm::length(back.position - c.position), 0.0f, 1e-4f);
}

TEST(CameraControls, OrbitPitchStopsShortOfThePole) {
  const Camera c = test_camera();
  const Camera over = orbit_camera(c, 0.0f, -500.0f);  // dragging far down: the camera rises to the pole
  const glm::vec3 offset = glm::normalize(over.position - over.target);
  const float elevation = glm::degrees(std::asin(glm::dot(offset, glm::vec3(0, 1, 0))));
  EXPECT_NEAR(elevation, 89.0f, 1e-3f);
  EXPECT_NEAR(distance(over), distance(c), 1e-4f);
}

TEST(CameraControls, DollyScalesTheDistanceAndOrthographicViewHeight) {
  const Camera c = test_camera();
  EXPECT_NEAR(distance(dolly_camera(c, 0.5f)), 0.5f * distance(c), 1e-5f);
  EXPECT_NEAR(distance(dolly_camera(c, 2.0f)), 2.0f * distance(c), 1e-4f);
  // Never through the target: at least twice the near plane.
  EXPECT_GE(distance(dolly_camera(c, 1e-6f)), 2.0f * c.near_plane - 1e-6f);
  Camera ortho = c;
  ortho.projection = Projection::Orthographic;
  const Camera d = dolly_camera(ortho, 0.25f);
  EXPECT_FLOAT_EQ(d.view_height, 0.25f * ortho.view_height);
  EXPECT_EQ(d.position, ortho.position);
}

TEST(CameraControls, FlyMovesPositionAndTargetTogether) {
  const Camera c = test_camera();
  const Camera f = fly_camera(c, {0.0f, 0.0f, 1.0f});
  const glm::vec3 forward = glm::normalize(c.target - c.position);
  EXPECT_NEAR(glm::length(f.position - (c.position + forward)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length((f.target - f.position) - (c.target - c.position)), 0.0f, 1e-5f);
  const Camera r = fly_camera(c, {1.0f, 0.0f, 0.0f});
  EXPECT_NEAR(glm::dot(r.position - c.position, forward), 0.0f, 1e-5f);  // sideways
  EXPECT_NEAR(glm::length(r.position - c.position), 1.0f, 1e-5f);
}

TEST(CameraControls, LookKeepsThePositionAndTurnsTheView) {
  const Camera c = test_camera();
  const Camera l = look_camera(c, 90.0f, 0.0f);
  EXPECT_EQ(l.position, c.position);
  EXPECT_NEAR(distance(l), distance(c), 1e-4f);
  // Yaw about the up axis: the horizontal parts of the old and new view directions are at 90 degrees.
  glm::vec3 before = c.target - c.position, after = l.target - l.position;
  before.y = after.y = 0.0f;
  EXPECT_NEAR(glm::dot(glm::normalize(before), glm::normalize(after)), 0.0f, 1e-4f);
}

TEST(DisplayCompose, SplitTakesColumnsLeftOfTheEdgeFromTheFirstImage) {
  const Image a(10, 3, glm::vec3(1.0f)), b(10, 3, glm::vec3(0.0f));
  const Image s = split_images(a, b, 0.3f);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 10; ++x) EXPECT_EQ(s.at(x, y).r, x < 3 ? 1.0f : 0.0f) << x;
  EXPECT_EQ(split_images(a, b, 0.0f).at(0, 0).r, 0.0f);
  EXPECT_EQ(split_images(a, b, 1.0f).at(9, 2).r, 1.0f);
}

TEST(DisplayCompose, BlendIsTheBaseAtZeroAndTheOverlayAtOne) {
  const Image a(4, 4, glm::vec3(0.2f, 0.4f, 0.6f)), b(4, 4, glm::vec3(1.0f, 0.0f, 0.5f));
  EXPECT_EQ(blend_images(a, b, 0.0f).at(1, 1), a.at(1, 1));
  EXPECT_EQ(blend_images(a, b, 1.0f).at(1, 1), b.at(1, 1));
  EXPECT_NEAR(blend_images(a, b, 0.5f).at(2, 3).r, 0.6f, 1e-6f);
}

TEST(DisplayCompose, ErrorMapIsZeroForTheReferenceItselfAndBrightWhereItDiffers) {
  Image reference(8, 8, glm::vec3(0.5f)), method = reference;
  method.at(3, 4) = glm::vec3(5.0f);
  const Image none = error_map_display(reference, reference);
  const Image some = error_map_display(method, reference);
  EXPECT_EQ(none.at(3, 4), none.at(0, 0));
  EXPECT_GT(some.at(3, 4).r + some.at(3, 4).g, some.at(0, 0).r + some.at(0, 0).g + 0.5f);
}

TEST(DisplayCompose, Rgba8QuantisesAsThePngWriter) {
  Image display(3, 1);
  display.at(0, 0) = glm::vec3(0.0f, 0.5f, 1.0f);
  display.at(1, 0) = glm::vec3(-1.0f, 2.0f, 0.25f);
  display.at(2, 0) = glm::vec3(1.0f / 255.0f, 254.6f / 255.0f, 0.0f);
  test::ScratchDirectory dir;
  write_png(dir / "x.png", display);
  const Image read = read_ldr_image(dir / "x.png");
  const auto rgba = to_rgba8(display);
  for (int x = 0; x < 3; ++x) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(rgba[x * 4 + c], std::lround(read.at(x, 0)[c] * 255.0f)) << x << "," << c;
    EXPECT_EQ(rgba[x * 4 + 3], 255);
  }
}

class ViewScript : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& text) {
    const auto p = dir / "script.txt";
    std::ofstream(p) << text;
    return p;
  }
  /// The message of the InputError reading `text` throws ("" when it reads).
  std::string error_of(const std::string& text) {
    try {
      read_view_script(write(text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  test::ScratchDirectory dir;
};

TEST_F(ViewScript, ReadsCommandsSkippingCommentsAndBlankLines) {
  const auto commands = read_view_script(write("# a comment\n\nmethod lean  # switch\nframe 3\nscreenshot out/x.exr\nquit\n"));
  ASSERT_EQ(commands.size(), 4u);
  EXPECT_EQ(commands[0].verb, "method");
  EXPECT_EQ(commands[0].line, 3);
  EXPECT_EQ(commands[0].args, std::vector<std::string>{"lean"});
  EXPECT_EQ(commands[1].args, std::vector<std::string>{"3"});
  EXPECT_EQ(commands[3].verb, "quit");
}

TEST_F(ViewScript, BadLinesNameTheFileTheLineTheValueAndWhatIsAllowed) {
  auto expect = [&](const std::string& text, std::initializer_list<const char*> fragments) {
    const std::string e = error_of(text);
    ASSERT_FALSE(e.empty()) << text;
    EXPECT_NE(e.find("script.txt:"), std::string::npos) << e;
    for (const char* f : fragments) EXPECT_NE(e.find(f), std::string::npos) << "'" << f << "' not in: " << e;
  };
  expect("method lean\nzoom 3\n", {":2:", "unknown command 'zoom'", "allowed:", "screenshot"});
  expect("frame\n", {":1:", "frame takes 1 argument", "not 0"});
  expect("frame two\n", {"'two' is not a number"});
  expect("frame 1.5\n", {"'1.5' is not a whole number"});
  expect("mode sideways\n", {"mode 'sideways'", "single, split, flip"});
  expect("param kappa\n", {"expected NAME=VALUE"});
  expect("error-overlay maybe\n", {"'maybe'", "on, off"});
  expect("window-screenshot shot.jpg\n", {"allowed: a .png file name"});
  expect("wait -2\n", {"allowed: 0 or more frames"});
  expect("magnify 3 4\n", {"magnify X Y ZOOM"});
  expect("magnify 3 4 0\n", {"zoom 0", "allowed: 2 .. 32"});
  expect("wait 333333333333333333333333\n", {"out of range", "1000000000"});  // fuzz_view_script: past int
  expect("magnify -1 4 8\n", {"magnify -1 4", "0 or more"});
  expect("error-overlay on 2\n", {"opacity 2", "0 .. 1"});
  EXPECT_EQ(error_of(""), "");  // an empty script reads
  EXPECT_EQ(error_of("\n# nothing\n"), "");
}

TEST_F(ViewScript, AMissingFileIsNamed) {
  try {
    read_view_script(dir / "missing.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace glintlab
