// Fuzz target: normal maps from image files (PNG; stb_image also takes JPEG, TGA, BMP and the other
// formats it knows by their magic). InputError is the expected outcome for bad input; anything
// else is a finding (docs/fuzzing.md).
#include "core/error.hpp"
#include "fuzz_input.hpp"
#include "scene/normal_map.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = glintlab::fuzz::write_input(data, size, "input.png");
  try {
    (void)glintlab::load_normal_map(path);
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
