#include "core/exr_header_check.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/image_io.hpp"

namespace glintlab {

namespace {

// Version-field flag (OpenEXR file layout, "Version Field").
constexpr std::uint32_t kMultipartFlag = 0x1000;
constexpr std::size_t kMaxNameLength = 255;

// Scanlines per chunk of each compression (OpenEXR file layout, "Compression").
std::optional<std::int64_t> lines_per_chunk(std::uint8_t compression) {
  constexpr std::int64_t lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  if (compression >= std::size(lines)) return std::nullopt;
  return lines[compression];
}

// OpenEXR reads a value of a known type by its type, not by the size the header declares: the
// declared size must then be that size, or the reading here and OpenEXR's would part ways (and a
// later attribute's size seen by OpenEXR would go unchecked). Types whose size varies: nullopt.
std::optional<std::int64_t> fixed_size(const std::string& type) {
  static const std::pair<const char*, std::int64_t> sizes[] = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36},
      {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},
      {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"deepImageState", 1}};
  for (const auto& [name, size] : sizes)
    if (type == name) return size;
  return std::nullopt;
}

class HeaderReader {
 public:
  HeaderReader(const std::filesystem::path& path, std::ifstream& in, std::uintmax_t file_size)
      : path_(path), in_(in), file_size_(file_size) {}

  std::optional<std::string> string() {
    std::string s;
    for (char c; in_.get(c);) {
      if (c == '\0') return s;
      if (s.size() == kMaxNameLength) return std::nullopt;
      s.push_back(c);
    }
    return std::nullopt;
  }

  template <typename T>
  std::optional<T> value() {
    T v{};
    if (!in_.read(reinterpret_cast<char*>(&v), sizeof v)) return std::nullopt;
    return v;  // EXR is little-endian, like every machine glintlab runs on
  }

  [[nodiscard]] std::uintmax_t remaining() {
    const auto at = static_cast<std::uintmax_t>(in_.tellg());
    return at < file_size_ ? file_size_ - at : 0;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_.string() + ": EXR " + what + " (the file has " + std::to_string(file_size_) + " bytes)");
  }

  // The offset table lists every chunk in 8 bytes.
  void require_chunks(std::int64_t chunks, const std::string& what) const {
    if (chunks < 0 || static_cast<std::uintmax_t>(chunks) > file_size_ / 8)
      fail(what + " needs " + std::to_string(chunks) + " chunks; allowed: at most 1 per 8 bytes of the file");
  }

  std::istream& stream() { return in_; }

 private:
  const std::filesystem::path& path_;
  std::ifstream& in_;
  std::uintmax_t file_size_;
};

struct PartHeader {
  std::optional<std::int64_t> width, height;
  std::optional<std::uint8_t> compression;
  std::optional<std::int64_t> tile_width, tile_height;
};

// Reads one header's attributes up to its terminating null byte; false if it is unreadable
// (OpenEXR then says why) or empty (the end of a multi-part file's headers).
bool read_header(HeaderReader& r, bool multipart, const std::filesystem::path& path) {
  PartHeader part;
  bool any = false;
  for (;;) {
    const auto name = r.string();
    if (!name) return false;
    if (name->empty()) break;
    any = true;
    const auto type = r.string();
    const auto size = r.value<std::int32_t>();
    if (!type || !size) return false;
    if (*size < 0 || static_cast<std::uintmax_t>(*size) > r.remaining())
      r.fail("header attribute '" + *name + "' (" + *type + ") claims " + std::to_string(*size) +
             " bytes; allowed: at most the " + std::to_string(r.remaining()) + " bytes after it");
    const auto end = r.stream().tellg() + std::streamoff{*size};
    std::int64_t holds = *size;  // what OpenEXR will read
    if (const auto fixed = fixed_size(*type)) {
      holds = *fixed;
    } else if (*type == "chlist") {  // entries (a name, 16 bytes) up to an empty name
      holds = 0;
      for (;;) {
        const auto channel = r.string();
        if (!channel) return false;
        holds += static_cast<std::int64_t>(channel->size()) + 1;
        if (channel->empty()) break;
        holds += 16;
        r.stream().seekg(16, std::ios::cur);
      }
    } else if (*type == "preview") {  // width, height, then 4 bytes per pixel
      const auto w = r.value<std::uint32_t>(), h = r.value<std::uint32_t>();
      if (!w || !h) return false;
      const std::uint64_t pixels = std::uint64_t{*w} * *h;  // cannot overflow; 4 * pixels can
      holds = pixels > (std::uint64_t{1} << 40) ? std::numeric_limits<std::int64_t>::max()
                                                 : 8 + 4 * static_cast<std::int64_t>(pixels);
    } else if (*type == "stringvector") {  // strings, each an int length and its characters
      for (std::int64_t read = 0; read < *size;) {
        const auto length = r.value<std::int32_t>();
        if (!length) return false;
        if (*length < 0 || *length > *size - read - 4)
          r.fail("header attribute '" + *name + "' (stringvector) holds a string of " + std::to_string(*length) +
                 " bytes; allowed: at most the " + std::to_string(*size - read - 4) + " bytes left of its value");
        read += 4 + *length;
        r.stream().seekg(*length, std::ios::cur);
      }
    }
    if (holds != *size)
      r.fail("header attribute '" + *name + "' (" + *type + ") declares " + std::to_string(*size) +
             " bytes but holds " + std::to_string(holds) + "; allowed: the size of its value");
    if (*name == "dataWindow" && *type == "box2i" && *size == 16) {
      const auto x0 = r.value<std::int32_t>(), y0 = r.value<std::int32_t>();
      const auto x1 = r.value<std::int32_t>(), y1 = r.value<std::int32_t>();
      if (!x0 || !y0 || !x1 || !y1) return false;
      part.width = std::int64_t{*x1} - *x0 + 1;
      part.height = std::int64_t{*y1} - *y0 + 1;
      check_image_size(path, *part.width, *part.height);
    } else if (*name == "compression" && *type == "compression" && *size == 1) {
      part.compression = r.value<std::uint8_t>();
    } else if (*name == "tiles" && *type == "tiledesc" && *size == 9) {
      const auto tw = r.value<std::uint32_t>(), th = r.value<std::uint32_t>();
      if (tw && th && *tw > 0 && *th > 0) part.tile_width = *tw, part.tile_height = *th;
    } else if (*name == "chunkCount" && *type == "int" && *size == 4) {
      if (const auto chunks = r.value<std::int32_t>()) r.require_chunks(*chunks, "chunkCount");
    }
    r.stream().seekg(end);
    if (!r.stream()) return false;
  }
  if (!part.width || !part.height) return any;
  if (part.tile_width) {
    const std::int64_t across = (*part.width + *part.tile_width - 1) / *part.tile_width;
    const std::int64_t down = (*part.height + *part.tile_height - 1) / *part.tile_height;
    r.require_chunks(across * down, "a tiled image of " + std::to_string(*part.width) + "x" +
                                        std::to_string(*part.height) + " in tiles of " +
                                        std::to_string(*part.tile_width) + "x" + std::to_string(*part.tile_height));
  } else if (!multipart && part.compression) {
    if (const auto lines = lines_per_chunk(*part.compression))
      r.require_chunks((*part.height + *lines - 1) / *lines,
                       "a scanline image " + std::to_string(*part.height) + " lines high");
  }
  return any;
}

}  // namespace

void check_exr_header(const std::filesystem::path& path) {
  std::error_code ec;
  const auto file_size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return;  // OpenEXR says why
  HeaderReader r(path, in, file_size);
  const auto magic = r.value<std::int32_t>();
  const auto version = r.value<std::uint32_t>();
  if (!magic || *magic != 20000630 || !version) return;
  const bool multipart = (*version & kMultipartFlag) != 0;
  while (read_header(r, multipart, path) && multipart) {
  }
}

}  // namespace glintlab
