// A normal-map image whose header claims an absurd size (fuzz/fuzz_png.cpp, docs/fuzzing.md) is
// InputError naming the file, the size and the limit, before anything of that size is allocated.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "scene/normal_map.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

TEST(HostileNormalMaps, PngClaiming60000SquaredIsRefused) {
  const test::ScratchDirectory dir;
  // Signature, IHDR 60000x60000 RGB8 (stb_image does not check CRCs), IEND.
  const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                               0, 0, 0xea, 0x60, 0, 0, 0xea, 0x60, 8, 2, 0, 0, 0, 0, 0, 0, 0,
                               0, 0, 0, 0, 'I', 'E', 'N', 'D', 0, 0, 0, 0};
  std::ofstream(dir / "normals.png", std::ios::binary).write(reinterpret_cast<const char*>(png), sizeof png);
  try {
    (void)load_normal_map(dir / "normals.png");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("normals.png"), std::string::npos) << message;
    EXPECT_NE(message.find("60000x60000"), std::string::npos) << message;
    EXPECT_NE(message.find("16384"), std::string::npos) << message;
  }
}
