// Fuzz target: normal maps from image files (PNG; stb_image also takes JPEG, TGA, BMP and the other
// formats it knows by their magic). InputError is the expected outcome for bad input; anything
// else is a finding (docs/fuzzing.md).
//
// stb_image takes a TGA or BMP cut short as whole, so 27 bytes can make a valid 2573x5658 image:
// decoding it is honest work within the limits (seconds under the sanitizers), not a bug, so
// inputs over a megapixel are skipped. Sizes past the limits still run (the loader must refuse
// them before decoding).
#include <stb/stb_image.h>

#include <string_view>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "core/jpeg_header_check.hpp"
#include "fuzz_input.hpp"
#include "scene/normal_maps/normal_map.hpp"

namespace {

// The formats read_ldr_image refuses by their magic (PSD, GIF, HDR, PIC, PNM) never reach stb's
// decoders, so they must not reach stbi_info here either.
bool refused_format(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (std::string_view magic : {"8BPS", "GIF8", "#?", "\x53\x80\xf6\x34", "P5", "P6"})
    if (bytes.substr(0, magic.size()) == magic) return true;
  return false;
}

}  // namespace

// Nor a JPEG whose Huffman tables read_ldr_image refuses (stb_image 2.27 overflows on them).
bool refused_jpeg(const std::filesystem::path& path) {
  try {
    glintlab::check_jpeg_header(path);
    return false;
  } catch (const glintlab::InputError&) {
    return true;
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = glintlab::fuzz::write_input(data, size, "input.png");
  int width = 0, height = 0, channels = 0;
  if (!refused_format(data, size) && !refused_jpeg(path) && stbi_info_from_memory(data, static_cast<int>(size), &width, &height, &channels) &&
      width <= glintlab::kMaxImageSide && height <= glintlab::kMaxImageSide &&
      std::int64_t{width} * height > (1 << 20) && std::int64_t{width} * height <= glintlab::kMaxImagePixels)
    return -1;  // not kept in the corpus
  try {
    (void)glintlab::load_normal_map(path);
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
