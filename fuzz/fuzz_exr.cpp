// Fuzz target: EXR images (OpenEXR through read_exr: the main RGB layer, then a named one as the
// reference cache reads them). InputError is the expected outcome for bad input; anything else is
// a finding (docs/fuzzing.md).
#include "core/error.hpp"
#include "core/image_io.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = glintlab::fuzz::write_input(data, size, "input.exr");
  try {
    (void)glintlab::read_exr(path);
    (void)glintlab::read_exr(path, "specular");
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
