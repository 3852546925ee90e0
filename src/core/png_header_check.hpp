#pragma once
// A look at a PNG file's chunks before stb_image reads it: stb_image allocates what a chunk's
// length declares (87 bytes made it allocate 1.4 GB for one IDAT) before it reads the data.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <utility>

namespace glintlab {

/// For a file with the PNG signature: throws InputError naming the file, the chunk and the
/// length when a chunk claims more bytes than the file has left, and returns the IHDR's width and
/// height. For any other file: nullopt (stb_image knows other formats by their magic).
std::optional<std::pair<std::int64_t, std::int64_t>> check_png_header(const std::filesystem::path& path);

}  // namespace glintlab
