#pragma once
// A look at a JPEG file's Huffman tables before stb_image reads it: stb_image 2.27 (Debian 12)
// does not check that a table's code counts sum to at most 256, and writes past the table's
// arrays when they do (fixed in stb_image 2.28).
#include <filesystem>

namespace glintlab {

/// For a file that starts like a JPEG: throws InputError naming the file when a Huffman table
/// (DHT segment) declares more than 256 codes. Any other file, or anything else wrong, is left to
/// stb_image.
void check_jpeg_header(const std::filesystem::path& path);

}  // namespace glintlab
