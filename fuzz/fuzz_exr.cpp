// Fuzz target: EXR images (OpenEXR through read_exr: the main RGB layer, then a named one as the
// reference cache reads them). InputError is the expected outcome for bad input; anything else is
// a finding (docs/fuzzing.md).
//
// A compressed EXR of a few kilobytes can hold a valid 64-Mpixel image: reading one is honest work
// within the limits, not a bug, so inputs whose data window is over a megapixel are skipped. Sizes
// past the limits still run (the reader must refuse them before allocating).
#include <cstring>
#include <string_view>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "fuzz_input.hpp"

namespace {

bool large_but_allowed(const std::uint8_t* data, std::size_t size) {
  constexpr std::string_view attribute("dataWindow\0box2i\0\x10\0\0\0", 21);
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (auto at = bytes.find(attribute); at != std::string_view::npos && at + 37 <= size;
       at = bytes.find(attribute, at + 1)) {
    std::int32_t box[4];
    std::memcpy(box, data + at + attribute.size(), sizeof box);
    const std::int64_t width = std::int64_t{box[2]} - box[0] + 1, height = std::int64_t{box[3]} - box[1] + 1;
    if (width >= 1 && height >= 1 && width <= glintlab::kMaxImageSide && height <= glintlab::kMaxImageSide &&
        width * height > (1 << 20) &&
        width * height <= glintlab::kMaxImagePixels)
      return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (large_but_allowed(data, size)) return -1;  // not kept in the corpus
  const auto path = glintlab::fuzz::write_input(data, size, "input.exr");
  try {
    (void)glintlab::read_exr(path);
    (void)glintlab::read_exr(path, "specular");
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
