// Fuzz target: scene files (TOML through parse_scene: every table, key, range and reference).
// InputError is the expected outcome for bad input; anything else is a finding (docs/fuzzing.md).
//
// Valid scenes may ask for seconds of honest work (a 8192^2 normal map of 4096 waves, a sphere of
// 65536 segments); that cost is documented and bounded by the parser's ranges, not a parser bug, so
// such inputs are skipped: the fuzzer spends its time on parsing. Values above the ranges still
// run (the parser must reject them).
#include <array>
#include <string_view>
#include <toml++/toml.h>

#include "core/error.hpp"
#include "core/image.hpp"
#include "core/image_io.hpp"
#include "fuzz_input.hpp"
#include "scene/scene_loader.hpp"

namespace {

constexpr std::int64_t kCheapSize = 64;        // resolution, segments, waves ... up to this run
constexpr std::int64_t kLargestRangeMax = 65536;  // no key that sizes work allows more

bool sizes_work(std::string_view key) {
  constexpr std::array<std::string_view, 8> keys = {"resolution", "waves", "cells", "max_frequency",
                                                    "segments", "rings", "subdivisions", "sides"};
  for (auto k : keys)
    if (k == key) return true;
  return false;
}

bool expensive(const toml::node& node);

bool expensive_table(const toml::table& table) {
  // A normal-map generator defaults to resolution 512: only an explicit small one is cheap.
  if (table.contains("generator")) {
    // value_exact: toml++'s value<int64_t>() casts a float such as 1e39 to an integer before
    // checking it fits (UB, found by this target in its own filter).
    const auto resolution = table["resolution"].value_exact<std::int64_t>();
    if (!resolution || (*resolution > kCheapSize && *resolution <= kLargestRangeMax)) return true;
  }
  for (const auto& [key, value] : table) {
    if (const auto n = value.value_exact<std::int64_t>(); n && sizes_work(key.str()) && *n > kCheapSize &&
                                                    *n <= kLargestRangeMax)
      return true;
    if (expensive(value)) return true;
  }
  return false;
}

bool expensive(const toml::node& node) {
  if (const auto* table = node.as_table()) return expensive_table(*table);
  if (const auto* array = node.as_array())
    for (const auto& element : *array)
      if (expensive(element)) return true;
  return false;
}

}  // namespace

// The scratch directory holds a small mesh and normal map, so `file = "mesh.obj"` and
// `file = "normals.png"` (in the dictionary) reach the loaders through the parser.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const auto& dir = glintlab::fuzz::scratch_directory();
  constexpr std::string_view obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  (void)glintlab::fuzz::write_input(reinterpret_cast<const std::uint8_t*>(obj.data()), obj.size(), "mesh.obj");
  glintlab::write_png(dir / "normals.png", glintlab::Image(4, 4, glm::vec3(0.5f, 0.5f, 1.0f)));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    if (expensive(toml::parse(text))) return -1;  // not kept in the corpus
  } catch (const toml::parse_error&) {
    // parse_scene must say so with an InputError
  }
  try {
    (void)glintlab::parse_scene(text, "fuzz.toml", glintlab::fuzz::scratch_directory());
  } catch (const glintlab::InputError&) {
  }
  return 0;
}
