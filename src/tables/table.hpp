#pragma once
// A precomputed table (docs/extending.md, "A precomputed table"): its CPU source (id,
// settings, generator; tables/table_source.hpp) and how it lives on the GPU: the texture it is
// uploaded to and the GLSL sampler that reads it. One file per table defines one of these, and
// tables/registry.cpp lists it once; the list gives it its texture unit.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gl/objects.hpp"
#include "tables/table_source.hpp"

namespace glintlab {

/// Bytes of a table on the GPU.
struct TableBytes {
  std::size_t base = 0;       ///< the texture's level 0
  std::size_t with_mips = 0;  ///< with its whole mip chain (= base without one)
};

/// A constant of the table's layout that its GLSL reads (GLINT_LEVELS, LTC_TABLE_SIZE), taken
/// from the generator's own settings and emitted into generated/gpu_contract.glsl as
/// `#define <name> <value>`, so that no shader restates it.
struct TableConstant {
  std::string name;  ///< upper snake case, prefixed by the table's family (GLINT_, LTC_)
  double value;
  bool integer;  ///< an int in GLSL; else a float

  static TableConstant of_int(std::string name, int value) { return {std::move(name), double(value), true}; }
  static TableConstant of_float(std::string name, float value) { return {std::move(name), double(value), false}; }
  /// The GLSL literal: "192", or the float in full precision with a point or exponent ("64.0", "0.353553385").
  [[nodiscard]] std::string glsl_value() const;
};

struct Table {
  TableSource source;
  /// The GLSL sampler that reads it, declared `layout(binding = TABLE_UNIT_<ID>)` (table_define()).
  std::string sampler;
  /// Its size on the GPU, known without a GL context (checked against the upload by a test).
  TableBytes gpu_bytes;
  /// Makes the texture from the values (a current GL context is needed).
  std::function<gl::Texture(std::span<const float>)> upload;
  /// The GLSL constants of its layout (tables/registry.cpp's table_defines() emits them; two
  /// tables may declare one name only with one value, e.g. the two LTC tables' size).
  std::vector<TableConstant> glsl_constants = {};
  /// The texture unit it is bound to: set by the registry (tables/registry.cpp).
  int unit = -1;
};

/// Bytes of a texture of `texels` texels of `texel_bytes` bytes on each of `layers` layers, with
/// its 1D mip chain (levels of texels / 2^m, down to 1).
TableBytes mip_chain_bytes_1d(int texels, int layers, std::size_t texel_bytes);

}  // namespace glintlab
