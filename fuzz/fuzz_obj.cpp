// Fuzz target: Wavefront OBJ meshes (the line-by-line pre-check, tinyobjloader, mesh validation).
// InputError is the expected outcome for bad input; anything else is a finding (docs/fuzzing.md).
#include "core/error.hpp"
#include "fuzz_input.hpp"
#include "scene/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = glintlab::fuzz::write_input(data, size, "input.obj");
  try {
    (void)glintlab::load_mesh_file(path);
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
