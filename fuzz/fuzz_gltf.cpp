// Fuzz target: glTF 2.0 import (geometry, materials, textures, lights, cameras), both forms: an
// input that starts with the binary magic "glTF" is imported as .glb, any other as .gltf (JSON). InputError is the expected outcome for bad input;
// anything else is a finding (docs/fuzzing.md).
#include <cstring>

#include "core/error.hpp"
#include "fuzz_input.hpp"
#include "scene/gltf/gltf_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = glintlab::fuzz::write_input(data, size, binary ? "input.glb" : "input.gltf");
  try {
    (void)glintlab::import_gltf(path);
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
