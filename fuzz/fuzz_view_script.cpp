// Fuzz target: viewer scripts (read_view_script: verbs, argument counts, numbers; what is checked
// before a window opens). InputError is the expected outcome for bad input; anything else is a
// finding (docs/fuzzing.md).
#include "core/error.hpp"
#include "fuzz_input.hpp"
#include "view/view_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = glintlab::fuzz::write_input(data, size, "script.txt");
  try {
    (void)glintlab::read_view_script(path);
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
