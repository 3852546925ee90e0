#pragma once
// Image files: linear EXR (float, with named layers) and 8-bit sRGB PNG. All writes are atomic.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"

namespace glintlab {

/// A named layer of an EXR file; the empty name is the main RGB layer.
struct ImageLayer {
  std::string name;
  const Image* image;
};

/// The largest image the readers accept, checked against the file's header before any pixel is
/// allocated (a header can claim any size): the film limits of a scene file (docs/scene-format.md).
inline constexpr int kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 64ll << 20;
/// Throws InputError naming the file, the size and the limits when width x height exceeds them
/// (or is not a size at all: below 1).
void check_image_size(const std::filesystem::path& path, std::int64_t width, std::int64_t height);

void write_exr(const std::filesystem::path& path, const std::vector<ImageLayer>& layers);
/// Reads one layer ("" = main RGB). Throws InputError naming the file if it is missing or broken,
/// or larger than kMaxImageSide / kMaxImagePixels.
Image read_exr(const std::filesystem::path& path, const std::string& layer = "");

/// Writes already display-encoded values in [0,1] as 8-bit PNG.
void write_png(const std::filesystem::path& path, const Image& display_image);

/// Reads a PNG/JPEG/TGA/BMP (8 or 16 bit) as raw values in [0,1] (no colour decoding).
/// Throws InputError naming the file if it is unreadable or larger than kMaxImageSide / kMaxImagePixels.
/// `file_channels`, if given, receives the file's own channel count (1 or 2: greyscale).
Image read_ldr_image(const std::filesystem::path& path, int* file_channels = nullptr);

}  // namespace glintlab
