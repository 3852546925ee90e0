#include <gtest/gtest.h>

#include <filesystem>

#include "core/colour.hpp"
#include "core/error.hpp"
#include "core/image_io.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

TEST(ImageIo, ExrRoundTripKeepsFloatsAndLayers) {
  const test::ScratchDirectory dir;
  Image a(5, 3), b(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      a.at(x, y) = glm::vec3(x * 1000.5f, y * 0.001f, -1.0f);
      b.at(x, y) = glm::vec3(static_cast<float>(x + y));
    }
  write_exr(dir / "t.exr", {{"", &a}, {"specular", &b}});
  const Image ra = read_exr(dir / "t.exr"), rb = read_exr(dir / "t.exr", "specular");
  EXPECT_EQ(ra.pixels(), a.pixels());
  EXPECT_EQ(rb.pixels(), b.pixels());
  EXPECT_THROW(read_exr(dir / "t.exr", "nope"), InputError);
  EXPECT_THROW(read_exr(dir / "missing.exr"), InputError);
  // Nothing but the committed file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);
}

TEST(Colour, TonemapIsMonotonicAndBounded) {
  float prev = -1.0f;
  for (float x = 0.0f; x < 100.0f; x += 0.25f) {
    const float y = srgb_encode(aces_filmic(x));
    EXPECT_GE(y, prev);
    EXPECT_LE(y, 1.0f);
    prev = y;
  }
  EXPECT_EQ(aces_filmic(0.0f), 0.0f);
  EXPECT_NEAR(srgb_encode(1.0f), 1.0f, 1e-6f);
}
