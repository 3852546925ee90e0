#pragma once
// The CPU half of a precomputed table (docs/extending.md, "A precomputed table"): what it
// is, what its values depend on and how they are generated. TableCache keeps the values on disk;
// the render layer's Table (tables/table.hpp) adds how they are uploaded and bound.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace glintlab {

/// Reports generation: (steps done, steps total). Called one call at a time, from any thread.
using TableProgressFn = std::function<void(int done, int total)>;

struct TableSource {
  std::string id;     ///< "glint-dictionary": names the cache file and GLSL's TABLE_UNIT_<ID>
  std::string title;  ///< shown by `glintlab info` and `glintlab methods`
  /// The generator's version: bump it whenever generate() would return other values for the same
  /// settings, so that no cache entry of the old generator is read.
  std::uint32_t version = 1;
  /// Every setting the values depend on, as "name=value" separated by spaces (floats in full
  /// precision): hashed into the cache key, stored in the entry and compared when it is read.
  std::string settings;
  std::size_t value_count = 0;  ///< floats generate() returns; their layout is the table's own
  /// The values, reporting progress through the callback; never prints.
  std::function<std::vector<float>(const TableProgressFn&)> generate;
  /// Why values read from the cache cannot be this table's, or "" if they can (optional: the
  /// cache already checks their count and checksum).
  std::function<std::string(std::span<const float>)> check = {};
};

}  // namespace glintlab
