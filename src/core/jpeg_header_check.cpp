#include "core/jpeg_header_check.hpp"

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace glintlab {

namespace {

// The segments as stb_image walks them: a marker (0xFF, fill bytes, a code; stb_image skips any
// other byte where a marker belongs), a 16-bit length for all but the standalone markers, and
// after a scan header its entropy-coded data up to the next marker (0xFF followed by neither
// 0x00, a restart code, nor another fill byte).
class JpegWalker {
 public:
  JpegWalker(const std::filesystem::path& path, std::vector<unsigned char> bytes)
      : path_(path), bytes_(std::move(bytes)) {}

  // From after the SOI marker at `at`.
  void check(std::size_t at) const {
    while (at + 1 < bytes_.size()) {
      if (bytes_[at] != 0xFF) {  // not a marker where one belongs: stb_image skips to the next 0xFF
        ++at;
        continue;
      }
      while (at + 1 < bytes_.size() && bytes_[at + 1] == 0xFF) ++at;
      const unsigned char marker = byte(at + 1);
      at += 2;
      if (marker == 0xD9) return;                                    // end of image
      if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) continue;  // no length
      const std::size_t length = static_cast<std::size_t>(byte(at)) << 8 | byte(at + 1);
      if (length < 2) return;
      if (marker == 0xC4) check_huffman_tables(at + 2, static_cast<long>(length) - 2);
      at += length;
      if (marker == 0xDA) at = next_marker(at);
    }
  }

 private:
  // stb_image reads zeros past the end of a file.
  [[nodiscard]] unsigned char byte(std::size_t at) const { return at < bytes_.size() ? bytes_[at] : 0; }

  [[nodiscard]] std::size_t next_marker(std::size_t at) const {
    for (; at + 1 < bytes_.size(); ++at) {
      const unsigned char next = bytes_[at + 1];
      if (bytes_[at] == 0xFF && next != 0x00 && next != 0xFF && !(next >= 0xD0 && next <= 0xD7)) return at;
    }
    return bytes_.size();
  }

  // Tables as stbi__process_marker reads them: class and id, 16 code counts, then the codes.
  void check_huffman_tables(std::size_t at, long left) const {
    while (left > 0) {
      long codes = 0;
      for (std::size_t i = 0; i < 16; ++i) codes += byte(at + 1 + i);
      if (codes > 256)
        throw InputError(path_.string() + ": JPEG Huffman table declares " + std::to_string(codes) +
                         " codes; allowed: at most 256");
      at += 17 + static_cast<std::size_t>(codes);
      left -= 17 + codes;
    }
  }

  const std::filesystem::path& path_;
  std::vector<unsigned char> bytes_;
};

}  // namespace

void check_jpeg_header(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // SOI: 0xFF, any fill bytes 0xFF, 0xD8.
  std::size_t at = 0;
  if (bytes.empty() || bytes[0] != 0xFF) return;
  while (at + 1 < bytes.size() && bytes[at + 1] == 0xFF) ++at;
  if (at + 1 >= bytes.size() || bytes[at + 1] != 0xD8) return;
  JpegWalker(path, std::move(bytes)).check(at + 2);
}

}  // namespace glintlab
