#include "core/image_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string_view>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/error.hpp"
#include "core/exr_header_check.hpp"
#include "core/file_access.hpp"
#include "core/jpeg_header_check.hpp"
#include "core/png_header_check.hpp"

namespace glintlab {

namespace {
std::string channel_name(const std::string& layer, char c) {
  return layer.empty() ? std::string(1, c) : layer + "." + c;
}


// stb_image reads more formats than glintlab documents; the others (PSD, GIF, HDR, PIC, PNM) are
// refused by their magic before stb sees them: fewer decoders fed a user's bytes (stb's PNM
// header parser overflows a signed int on long numbers).
void require_documented_format(const std::filesystem::path& path) {
  char magic[4] = {};
  std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
  const std::pair<std::string_view, const char*> others[] = {
      {"8BPS", "PSD"}, {"GIF8", "GIF"}, {"#?", "Radiance HDR"}, {"\x53\x80\xf6\x34", "Softimage PIC"},
      {"P5", "PGM"}, {"P6", "PPM"}};
  for (const auto& [prefix, format] : others)
    if (std::string_view(magic, sizeof magic).substr(0, prefix.size()) == prefix)
      throw InputError(path.string() + ": a " + format + " image; allowed: PNG, JPEG, TGA or BMP");
}

}  // namespace

void check_image_size(const std::filesystem::path& path, std::int64_t width, std::int64_t height) {
  if (width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide &&
      width * height <= kMaxImagePixels)
    return;
  throw InputError(path.string() + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                   " is not allowed; allowed: 1 to " + std::to_string(kMaxImageSide) + " pixels per side, " +
                   std::to_string(kMaxImagePixels) + " pixels (64 Mpixels) in all");
}

void write_exr(const std::filesystem::path& path, const std::vector<ImageLayer>& layers) {
  if (layers.empty()) throw RuntimeFailure(path.string() + ": nothing to write");
  const int w = layers.front().image->width();
  const int h = layers.front().image->height();
  AtomicFile file(path);
  try {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    for (const auto& layer : layers) {
      for (int c = 0; c < 3; ++c) {
        const std::string name = channel_name(layer.name, "RGB"[c]);
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        auto* base = reinterpret_cast<char*>(const_cast<glm::vec3*>(layer.image->pixels().data())) +
                     c * sizeof(float);
        fb.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(glm::vec3), sizeof(glm::vec3) * w));
      }
    }
    Imf::OutputFile out(file.temp_path().c_str(), header, 1);
    out.setFrameBuffer(fb);
    out.writePixels(h);
  } catch (const std::exception& e) {
    throw RuntimeFailure(path.string() + ": cannot write EXR: " + e.what());
  }
  file.commit();
}

Image read_exr(const std::filesystem::path& path, const std::string& layer) {
  require_regular_file(path, "");
  check_exr_header(path);  // before OpenEXR allocates what the header claims
  try {
    Imf::InputFile in(path.c_str());
    const auto dw = in.header().dataWindow();
    check_image_size(path, std::int64_t{dw.max.x} - dw.min.x + 1, std::int64_t{dw.max.y} - dw.min.y + 1);
    const int w = dw.max.x - dw.min.x + 1;
    const int h = dw.max.y - dw.min.y + 1;
    Image img(w, h);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 3; ++c) {
      const std::string name = channel_name(layer, "RGB"[c]);
      if (!in.header().channels().findChannel(name))
        throw InputError(path.string() + ": EXR has no channel '" + name + "'");
      auto* base = reinterpret_cast<char*>(img.pixels().data()) + c * sizeof(float) -
                   (static_cast<std::ptrdiff_t>(dw.min.x) + static_cast<std::ptrdiff_t>(dw.min.y) * w) *
                       static_cast<std::ptrdiff_t>(sizeof(glm::vec3));
      fb.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(glm::vec3), sizeof(glm::vec3) * w));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return img;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": cannot read EXR: " + e.what());
  }
}

void write_png(const std::filesystem::path& path, const Image& img) {
  std::vector<std::uint8_t> bytes(img.pixel_count() * 3);
  for (std::size_t i = 0; i < img.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + c] = unorm8(img.pixels()[i][c]);
  AtomicFile file(path);
  if (!stbi_write_png(file.temp_path().c_str(), img.width(), img.height(), 3, bytes.data(),
                      img.width() * 3))
    throw RuntimeFailure(path.string() + ": cannot write PNG");
  file.commit();
}

Image read_ldr_image(const std::filesystem::path& path, int* file_channels) {
  int w = 0, h = 0, channels = 0;
  require_regular_file(path, "");
  require_documented_format(path);
  check_jpeg_header(path);
  // stb_image decodes the bytes read here, the ones the checks above walked: reading a file itself,
  // it rewinds only within its first 128 bytes and decodes stale buffer contents after a format
  // test that read further (docs/fuzzing.md, finding 16).
  const std::string file = read_regular_file(path, "", std::numeric_limits<int>::max());
  const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
  const int size = static_cast<int>(file.size());
  // Sizes before decoding: stb_image refuses one over 2^30 bytes only as "too large", without it.
  if (const auto png_size = check_png_header(path)) {
    check_image_size(path, png_size->first, png_size->second);
  } else if (stbi_info_from_memory(bytes, size, &w, &h, &channels)) {
    check_image_size(path, w, h);
  }
  const bool is16 = stbi_is_16_bit_from_memory(bytes, size);
  void* data = is16 ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &w, &h, &channels, 3))
                    : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &channels, 3));
  if (!data) {
    const char* why = stbi_failure_reason();
    throw InputError(path.string() + ": cannot read image (" + (why ? why : "unknown error") +
                     "); allowed: PNG, JPEG, TGA or BMP, 8 or 16 bits per channel, up to " +
                     std::to_string(kMaxImageSide) + " pixels per side");
  }
  if (file_channels) *file_channels = channels;
  Image img(w, h);
  const float scale = is16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
  for (std::size_t i = 0; i < img.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      img.pixels()[i][c] = scale * (is16 ? static_cast<float>(static_cast<std::uint16_t*>(data)[3 * i + c])
                                         : static_cast<float>(static_cast<std::uint8_t*>(data)[3 * i + c]));
  stbi_image_free(data);
  return img;
}

}  // namespace glintlab
