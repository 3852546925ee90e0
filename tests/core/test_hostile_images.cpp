// Image files whose headers claim more than they hold (found by fuzz/fuzz_exr.cpp and
// fuzz_png.cpp, docs/fuzzing.md): each is InputError naming the file, the value and the limit,
// raised before anything of the claimed size is allocated.
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cstdint>
#include <functional>
#include <iterator>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

namespace {

class Bytes {
 public:
  Bytes& u8(std::uint8_t v) { return raw(&v, 1); }
  Bytes& i32(std::int32_t v) { return raw(&v, 4); }  // EXR: little-endian, as the test machine
  Bytes& f32(float v) { return raw(&v, 4); }
  Bytes& be32(std::uint32_t v) { return u8(v >> 24).u8(v >> 16).u8(v >> 8).u8(v); }
  Bytes& text(const std::string& s, bool terminated = true) {
    raw(s.data(), s.size());
    return terminated ? u8(0) : *this;
  }
  void save(const std::filesystem::path& path) const {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data_.data()),
                                               static_cast<std::streamsize>(data_.size()));
  }

 private:
  Bytes& raw(const void* p, std::size_t n) {
    data_.insert(data_.end(), static_cast<const std::uint8_t*>(p), static_cast<const std::uint8_t*>(p) + n);
    return *this;
  }
  std::vector<std::uint8_t> data_;
};

// A scanline EXR header with R, G, B float channels over [0, width) x [0, height), and no pixels.
Bytes exr_header(std::int32_t width, std::int32_t height, std::uint8_t compression = 0) {
  Bytes b;
  b.i32(20000630).i32(2);
  b.text("channels").text("chlist").i32(3 * 18 + 1);
  for (const char* c : {"B", "G", "R"}) b.text(c).i32(2).u8(0).u8(0).u8(0).u8(0).i32(1).i32(1);
  b.u8(0);
  b.text("compression").text("compression").i32(1).u8(compression);
  for (const char* window : {"dataWindow", "displayWindow"})
    b.text(window).text("box2i").i32(16).i32(0).i32(0).i32(width - 1).i32(height - 1);
  b.text("lineOrder").text("lineOrder").i32(1).u8(0);
  b.text("pixelAspectRatio").text("float").i32(4).f32(1.0f);
  b.text("screenWindowCenter").text("v2f").i32(8).f32(0.0f).f32(0.0f);
  b.text("screenWindowWidth").text("float").i32(4).f32(1.0f);
  return b;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST(HostileImages, ExrClaimingHugeDataWindowIsRefused) {
  const test::ScratchDirectory dir;
  exr_header(60000, 60000).u8(0).save(dir / "huge.exr");
  const auto message = message_of([&] { (void)read_exr(dir / "huge.exr"); });
  EXPECT_NE(message.find("huge.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("60000x60000"), std::string::npos) << message;
  EXPECT_NE(message.find("16384"), std::string::npos) << message;
}

TEST(HostileImages, ExrAttributeLargerThanTheFileIsRefused) {
  // 141 bytes made OpenEXR allocate 1.6 GB for an unknown attribute's value before reading it.
  const test::ScratchDirectory dir;
  exr_header(2, 2).text("junk").text("opaque").i32(0x60000000).u8(0).save(dir / "attribute.exr");
  const auto message = message_of([&] { (void)read_exr(dir / "attribute.exr"); });
  EXPECT_NE(message.find("attribute.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("'junk'"), std::string::npos) << message;
  EXPECT_NE(message.find("1610612736"), std::string::npos) << message;
}

TEST(HostileImages, ExrWithMoreChunksThanItsOffsetTableCanListIsRefused) {
  // 4000 lines of uncompressed scanlines need 4000 offsets of 8 bytes; the file has a few hundred.
  const test::ScratchDirectory dir;
  exr_header(4000, 4000).u8(0).save(dir / "chunks.exr");
  const auto message = message_of([&] { (void)read_exr(dir / "chunks.exr"); });
  EXPECT_NE(message.find("chunks.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("4000 chunks"), std::string::npos) << message;
}

TEST(HostileImages, SmallExrStillReads) {
  const test::ScratchDirectory dir;
  const Image image(3, 2, glm::vec3(0.25f, 0.5f, 1.0f));
  write_exr(dir / "ok.exr", {{"", &image}});
  EXPECT_EQ(read_exr(dir / "ok.exr").pixels(), image.pixels());
}

TEST(HostileImages, PngClaimingHugeSizeIsRefusedBeforeDecoding) {
  const test::ScratchDirectory dir;
  Bytes png;
  png.u8(0x89).text("PNG\r\n\x1a\n", false);
  png.be32(13).text("IHDR", false).be32(60000).be32(60000).u8(8).u8(2).u8(0).u8(0).u8(0).be32(0);
  png.be32(0).text("IEND", false).be32(0);
  png.save(dir / "huge.png");
  const auto message = message_of([&] { (void)read_ldr_image(dir / "huge.png"); });
  EXPECT_NE(message.find("huge.png"), std::string::npos) << message;
  EXPECT_NE(message.find("60000x60000"), std::string::npos) << message;
  EXPECT_NE(message.find("16384"), std::string::npos) << message;
}

TEST(HostileImages, PngChunkLongerThanTheFileIsRefused) {
  // 87 bytes whose IDAT declared 1459617804 bytes: stb_image allocated that before reading.
  const test::ScratchDirectory dir;
  Bytes png;
  png.u8(0x89).text("PNG\r\n\x1a\n", false);
  png.be32(13).text("IHDR", false).be32(2).be32(2).u8(8).u8(2).u8(0).u8(0).u8(0).be32(0);
  png.be32(0x5700000c).text("IDAT", false).be32(0x789c6360).be32(0);
  png.save(dir / "chunk.png");
  const auto message = message_of([&] { (void)read_ldr_image(dir / "chunk.png"); });
  EXPECT_NE(message.find("chunk.png"), std::string::npos) << message;
  EXPECT_NE(message.find("'IDAT'"), std::string::npos) << message;
  EXPECT_NE(message.find("1459617804"), std::string::npos) << message;
}

TEST(HostileImages, SmallPngStillReads) {
  const test::ScratchDirectory dir;
  const Image image(3, 2, glm::vec3(0.0f, 0.5f, 1.0f));
  write_png(dir / "ok.png", image);
  const Image read = read_ldr_image(dir / "ok.png");
  ASSERT_EQ(read.width(), 3);
  EXPECT_NEAR(read.at(2, 1).y, 128.0f / 255.0f, 1e-6f);
}

TEST(HostileImages, ExrAttributeWhoseValueDisagreesWithItsSizeIsRefused) {
  // OpenEXR reads a channel list up to its empty name whatever size the header declares; 213
  // bytes declared 51 for one holding 55, and the next attribute, as OpenEXR read on, claimed
  // 1.7 GB that it allocated.
  const test::ScratchDirectory dir;
  Bytes b;
  b.i32(20000630).i32(2).text("channels").text("chlist").i32(51);
  for (const char* c : {"B", "G", "R"}) b.text(c).i32(2).u8(0).u8(0).u8(0).u8(0).i32(1).i32(1);
  b.u8(0).text("junk").text("opaque").i32(0x696c6863).u8(0);
  b.save(dir / "chlist.exr");
  const auto message = message_of([&] { (void)read_exr(dir / "chlist.exr"); });
  EXPECT_NE(message.find("chlist.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("'channels' (chlist) declares 51 bytes but holds 55"), std::string::npos) << message;
}

TEST(HostileImages, ExrPreviewLargerThanTheFileIsRefused) {
  const test::ScratchDirectory dir;
  exr_header(2, 2).text("preview").text("preview").i32(8).i32(60000).i32(60000).u8(0).save(dir / "preview.exr");
  const auto message = message_of([&] { (void)read_exr(dir / "preview.exr"); });
  EXPECT_NE(message.find("'preview' (preview) declares 8 bytes but holds 14400000008"), std::string::npos) << message;
}

TEST(HostileImages, UndocumentedImageFormatsAreRefusedByTheirMagic) {
  // A PPM header whose width overflowed stb_image's int parser (fuzz_png); PNG, JPEG, TGA and
  // BMP are what docs/scene-format.md allows.
  const test::ScratchDirectory dir;
  Bytes ppm;
  ppm.text("P6\n2222222222222222222222 1\n255\n", false).u8(0);
  ppm.save(dir / "image.ppm");
  const auto message = message_of([&] { (void)read_ldr_image(dir / "image.ppm"); });
  EXPECT_NE(message.find("image.ppm: a PPM image; allowed: PNG, JPEG, TGA or BMP"), std::string::npos) << message;
  Bytes gif;
  gif.text("GIF89a", false).u8(1).u8(0).u8(1).u8(0).u8(0).u8(0).u8(0);
  gif.save(dir / "image.gif");
  EXPECT_NE(message_of([&] { (void)read_ldr_image(dir / "image.gif"); }).find("a GIF image"), std::string::npos);
}

TEST(HostileImages, JpegHuffmanTableWithTooManyCodesIsRefused) {
  // fuzz_png: a DHT segment whose 16 counts sum past 256 made stb_image 2.27 write past its
  // Huffman table (UBSan: index 257 out of bounds).
  const test::ScratchDirectory dir;
  Bytes jpeg;
  jpeg.u8(0xFF).u8(0xD8).u8(0xFF).u8(0xC4).u8(0x00).u8(2 + 17);
  jpeg.u8(0x00);
  for (int i = 0; i < 16; ++i) jpeg.u8(0xC4);  // 16 x 196 codes
  jpeg.u8(0xFF).u8(0xD9);
  jpeg.save(dir / "huffman.jpg");
  const auto message = message_of([&] { (void)read_ldr_image(dir / "huffman.jpg"); });
  EXPECT_NE(message.find("huffman.jpg: JPEG Huffman table declares 3136 codes; allowed: at most 256"),
            std::string::npos)
      << message;
}

TEST(HostileImages, JpegHuffmanTableAfterFillBytesIsRefused) {
  // The same table behind fill bytes before SOI and a stray byte before DHT, which stb_image skips.
  const test::ScratchDirectory dir;
  Bytes jpeg;
  jpeg.u8(0xFF).u8(0xFF).u8(0xD8).u8(0x42).u8(0xFF).u8(0xC4).u8(0x01).u8(0x01);
  for (int i = 0; i < 8; ++i) jpeg.u8(0xC4);
  jpeg.save(dir / "fill.jpg");
  EXPECT_NE(message_of([&] { (void)read_ldr_image(dir / "fill.jpg"); }).find("JPEG Huffman table declares"),
            std::string::npos);
}

TEST(HostileImages, AJpegAfterManyFillBytesDecodesAsItself) {
  // fuzz/fuzz_png.cpp (docs/fuzzing.md, finding 16): stb_image reading a file itself rewinds only
  // within its first 128 bytes; when the refill during its format test is short (the file ends),
  // it decodes stale buffer bytes: 208 fill bytes, then a Huffman table whose counts came from the
  // stale bytes overflowed its arrays (seen under UBSan: fuzz/corpus/png/finding-stale-buffer-*).
  // glintlab hands stb_image the bytes its checks walked, so the file is what it decodes.
  const glintlab::test::ScratchDirectory dir;
  std::vector<unsigned char> rgb(8 * 8 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>(i * 7);
  const auto plain = dir / "plain.jpg";
  ASSERT_NE(stbi_write_jpg(plain.c_str(), 8, 8, 3, rgb.data(), 95), 0);
  std::ifstream in(plain, std::ios::binary);
  const std::string jpeg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "filled.jpg", std::ios::binary) << std::string(208, '\xff') << jpeg;
  const glintlab::Image a = glintlab::read_ldr_image(plain), b = glintlab::read_ldr_image(dir / "filled.jpg");
  ASSERT_EQ(b.width(), 8);
  EXPECT_TRUE(a.pixels() == b.pixels());
  // The finding's own bytes: a table past its file, refused as bad input.
  std::ofstream(dir / "finding.jpg", std::ios::binary)
      << std::string(208, '\xff') << std::string("\xd8\xff\xc4\x47\x49\x00\x00\xff\x00", 9);
  EXPECT_THROW((void)glintlab::read_ldr_image(dir / "finding.jpg"), glintlab::InputError);
}
