// Normal-map files. A normal-map image whose header claims an absurd size (fuzz/fuzz_png.cpp,
// docs/fuzzing.md) is InputError naming the file, the size and the limit, before anything of that
// size is allocated. EXR maps hold raw normals: read back as written; a texel that is not finite,
// below the surface or far from unit length, missing channels or a truncated file are InputError
// naming the file (and the texel and its value). 16-bit PNGs keep their 16 bits.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/normal_maps/normal_map.hpp"
#include "scratch_directory.hpp"
#include "test_scenes.hpp"

using namespace glintlab;

namespace {

/// A w x h EXR of float channels `names` (e.g. "RGB", "RG", "Y"), pixel (x, y) from the top-left
/// holding values[(y w + x) * names.size() + c].
void write_channels_exr(const std::filesystem::path& path, int w, int h, const std::string& names,
                        std::vector<float> values) {
  Imf::Header header(w, h);
  Imf::FrameBuffer fb;
  const std::size_t stride = names.size() * sizeof(float);
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string name(1, names[c]);
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data() + c), stride, stride * w));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(fb);
  out.writePixels(h);
}

/// 3 x 2 raw normals, not all of unit length, with `bad` at texel (2, 1).
std::vector<float> normals_with(std::array<float, 3> bad) {
  std::vector<float> v = {0.0f, 0.0f, 1.0f, 0.3f, -0.2f, 0.9f, -0.6f, 0.0f, 0.8f,
                          0.1f, 0.1f, 1.2f, 0.0f, 0.5f, 0.7f, 0.0f, 0.0f, 1.0f};
  std::copy(bad.begin(), bad.end(), v.end() - 3);
  return v;
}

std::string message_of(const std::filesystem::path& path) {
  try {
    (void)load_normal_map(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// A PNG by hand (stb_image_write writes 8 bits only): zlib "stored" blocks, CRCs and Adler-32.
void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

std::uint32_t crc32(const unsigned char* p, std::size_t n) {
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

void chunk(std::vector<unsigned char>& png, const char* type, const std::vector<unsigned char>& data) {
  put32(png, static_cast<std::uint32_t>(data.size()));
  std::vector<unsigned char> body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  png.insert(png.end(), body.begin(), body.end());
  put32(png, crc32(body.data(), body.size()));
}

/// A 16-bit PNG of w x h pixels of `channels` (3: RGB, 1: grey), rgb[(y w + x) * channels + c],
/// row 0 at the top.
void write_png16(const std::filesystem::path& path, int w, int h, const std::vector<std::uint16_t>& rgb,
                 int channels = 3) {
  std::vector<unsigned char> raw;
  for (int y = 0; y < h; ++y) {
    raw.push_back(0);  // filter: none
    for (int i = 0; i < w * channels; ++i) {
      const std::uint16_t v = rgb[static_cast<std::size_t>(y * w * channels + i)];
      raw.push_back(static_cast<unsigned char>(v >> 8));
      raw.push_back(static_cast<unsigned char>(v & 0xff));
    }
  }
  std::vector<unsigned char> z = {0x78, 0x01, 0x01};  // one final stored block
  z.push_back(static_cast<unsigned char>(raw.size() & 0xff));
  z.push_back(static_cast<unsigned char>(raw.size() >> 8));
  z.push_back(static_cast<unsigned char>(~raw.size() & 0xff));
  z.push_back(static_cast<unsigned char>((~raw.size() >> 8) & 0xff));
  z.insert(z.end(), raw.begin(), raw.end());
  std::uint32_t a = 1, b = 0;
  for (unsigned char c : raw) b = (b + (a = (a + c) % 65521)) % 65521;
  put32(z, (b << 16) | a);
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(w));
  put32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {16, static_cast<unsigned char>(channels == 3 ? 2 : 0), 0, 0, 0});  // 16 bits, RGB or grey
  chunk(png, "IHDR", ihdr);
  chunk(png, "IDAT", z);
  chunk(png, "IEND", {});
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
}

}  // namespace

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

TEST(NormalMapFiles, ExrHoldsRawNormalsBottomRowFirst) {
  const test::ScratchDirectory dir;
  const std::vector<float> v = normals_with({0.0f, 0.0f, 1.0f});
  for (const char* name : {"raw.exr", "raw.png"}) {  // an EXR by its content, whatever its name
    write_channels_exr(dir / name, 3, 2, "RGB", v);
    const NormalMap m = load_normal_map(dir / name);
    ASSERT_EQ(m.width, 3);
    ASSERT_EQ(m.height, 2);
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        const float* c = v.data() + (y * 3 + x) * 3;
        const glm::vec3 want = glm::normalize(glm::vec3(c[0], c[1], c[2]));
        // The file's top row is v = 1.
        const glm::vec3 got = m.normals[static_cast<std::size_t>((1 - y) * 3 + x)];
        EXPECT_LT(glm::length(got - want), 1e-6f) << name << " " << x << ", " << y;
      }
  }
}

TEST(NormalMapFiles, SixteenBitPngKeepsItsLowByte) {
  // Two texels that differ only in the low byte of red: one normal in 8 bits, two in 16.
  const test::ScratchDirectory dir;
  const std::vector<std::uint16_t> rgb = {0x8000, 0x8000, 0xffff, 0x80f0, 0x8000, 0xffff};
  write_png16(dir / "n16.png", 2, 1, rgb);
  const NormalMap m = load_normal_map(dir / "n16.png");
  ASSERT_EQ(m.normals.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const glm::vec3 c(rgb[3 * i] / 65535.0f, rgb[3 * i + 1] / 65535.0f, rgb[3 * i + 2] / 65535.0f);
    EXPECT_LT(glm::length(m.normals[i] - glm::normalize(2.0f * c - 1.0f)), 1e-6f) << i;
  }
  EXPECT_GT(m.normals[1].x - m.normals[0].x, 0.005f);
}

TEST(HostileNormalMaps, OffsetEncodedExrsAndGreyscaleImagesAreRefused) {
  const test::ScratchDirectory dir;
  // 0.5 (n + 1) of unit normals, as a PNG would hold them: every texel's length is within the
  // per-texel limits ((0.5, 0.5, 1) is 1.22), so only the whole map tells.
  std::vector<float> encoded, raw_positive;
  for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)),
                            glm::normalize(glm::vec3(-0.4f, 0.1f, 0.8f)), glm::vec3(0, 0, 1)}) {
    const glm::vec3 e = 0.5f * (n + 1.0f), p = glm::normalize(glm::abs(n) + glm::vec3(0.0f, 0.0f, 0.1f));
    encoded.insert(encoded.end(), {e.x, e.y, e.z});
    raw_positive.insert(raw_positive.end(), {p.x, p.y, p.z});
  }
  write_channels_exr(dir / "encoded.exr", 2, 2, "RGB", encoded);
  const std::string message = message_of(dir / "encoded.exr");
  for (const char* part : {"encoded.exr", "0.5 (n + 1)", "raw components"})
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  // Raw normals that all lean to +x and +y are normals, not an encoding.
  write_channels_exr(dir / "raw.exr", 2, 2, "RGB", raw_positive);
  EXPECT_EQ(message_of(dir / "raw.exr"), "no InputError");
  // A greyscale image has one value for x, y and z.
  write_png16(dir / "grey16.png", 2, 1, {0x8000, 0xffff}, 1);
  const std::string grey = message_of(dir / "grey16.png");
  for (const char* part : {"grey16.png", "greyscale", "RGB"})
    EXPECT_NE(grey.find(part), std::string::npos) << "'" << part << "' not in: " << grey;
}

TEST(HostileNormalMaps, ExrTexelsThatAreNoNormalsAreNamed) {
  const test::ScratchDirectory dir;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  struct Case {
    std::array<float, 3> texel;
    const char* value;
    const char* why;
  };
  for (const Case& c : {Case{{0.1f, nan, 0.9f}, "nan", "not finite"}, Case{{inf, 0.0f, 1.0f}, "inf", "not finite"},
                        Case{{0.6f, 0.8f, 0.0f}, "0.8, 0)", "z <= 0"}, Case{{0.0f, 0.0f, -1.0f}, "-1)", "z <= 0"},
                        Case{{0.1f, 0.1f, 0.3f}, "0.3)", "length"}, Case{{1.0f, 1.0f, 1.0f}, "1, 1, 1", "length"}}) {
    write_channels_exr(dir / "bad.exr", 3, 2, "RGB", normals_with(c.texel));
    const std::string message = message_of(dir / "bad.exr");
    for (const char* part : {"bad.exr", "texel (2, 1)", c.value, c.why})
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

TEST(HostileNormalMaps, ExrWithoutThreeChannelsOrCutShortIsNamed) {
  const test::ScratchDirectory dir;
  write_channels_exr(dir / "rg.exr", 2, 2, "RG", std::vector<float>(8, 0.5f));
  write_channels_exr(dir / "grey.exr", 2, 2, "Y", std::vector<float>(4, 1.0f));
  for (const char* name : {"rg.exr", "grey.exr"}) {
    const std::string message = message_of(dir / name);
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("no channel"), std::string::npos) << message;
  }
  std::vector<float> flat(16 * 16 * 3, 0.0f);
  for (std::size_t i = 2; i < flat.size(); i += 3) flat[i] = 1.0f;
  write_channels_exr(dir / "cut.exr", 16, 16, "RGB", flat);
  ASSERT_EQ(load_normal_map(dir / "cut.exr").normals.size(), 256u);
  std::filesystem::resize_file(dir / "cut.exr", std::filesystem::file_size(dir / "cut.exr") * 2 / 3);
  EXPECT_NE(message_of(dir / "cut.exr").find("cut.exr"), std::string::npos) << message_of(dir / "cut.exr");
}

TEST(HostileNormalMaps, ABadExrNormalMapNamesTheSceneKeyAndTheTexel) {
  const test::ScratchDirectory dir;
  write_channels_exr(dir / "nan.exr", 3, 2, "RGB", normals_with({std::nanf(""), 0.0f, 1.0f}));
  try {
    static_cast<void>(test::TestScene()
                          .material("m", {{"normal_map", test::TomlKeys{{"file", "nan.exr"}}}})
                          .sphere("m")
                          .point_light({0, 2, 3})
                          .scene(dir.path()));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* part : {"normal_map", "'file'", "nan.exr", "texel (2, 1)", "nan"})
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}
