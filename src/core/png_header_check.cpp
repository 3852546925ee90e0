#include "core/png_header_check.hpp"

#include <cstring>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace glintlab {

namespace {
std::int64_t big_endian(const unsigned char* b) {
  return std::int64_t{b[0]} << 24 | std::int64_t{b[1]} << 16 | std::int64_t{b[2]} << 8 | b[3];
}
}  // namespace

std::optional<std::pair<std::int64_t, std::int64_t>> check_png_header(const std::filesystem::path& path) {
  std::error_code ec;
  const auto file_size = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
  std::ifstream in(path, std::ios::binary);
  unsigned char signature[8];
  if (ec || !in.read(reinterpret_cast<char*>(signature), 8) || std::memcmp(signature, "\x89PNG\r\n\x1a\n", 8) != 0)
    return std::nullopt;
  std::optional<std::pair<std::int64_t, std::int64_t>> size;
  // Each chunk: length (4 bytes, big-endian), type (4), data (length), CRC (4).
  for (std::int64_t at = 8; at + 8 <= file_size;) {
    unsigned char head[16];
    in.seekg(at);
    if (!in.read(reinterpret_cast<char*>(head), 8)) break;
    const std::int64_t length = big_endian(head);
    const std::string type(reinterpret_cast<const char*>(head + 4), 4);
    const std::int64_t left = file_size - (at + 8);
    if (length > left)
      throw InputError(path.string() + ": PNG chunk '" + type + "' claims " + std::to_string(length) +
                       " bytes; allowed: at most the " + std::to_string(left) + " bytes left in the file");
    if (type == "IHDR" && length >= 8 && in.read(reinterpret_cast<char*>(head + 8), 8))
      size = std::pair{big_endian(head + 8), big_endian(head + 12)};
    if (type == "IEND") break;
    at += 12 + length;
  }
  return size;
}

}  // namespace glintlab
