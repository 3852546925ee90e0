#pragma once
// What a program asks of a GPU, counted in its SPIR-V as a driver's compiler would first shape it
// (shader_stats/spirv_optimiser.hpp): operations, texture fetches, buffer loads, transcendental
// functions, branches, and accesses into thread-local arrays with an index that is not a
// constant. Such an array cannot live in registers: a GPU compiler spills it to local memory
// (off-chip, cached), where every access costs a memory round trip and the array's copies cost
// stores (docs/shader-statistics.md). Static counts: each instruction once, whatever branches a
// pixel takes; both sides of a branch are counted, as Mesa's llvmpipe runs them.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "shader_stats/spirv_module.hpp"

namespace glintlab {

struct ShaderStatistics {
  int operations = 0;         ///< instructions that compute (not labels, merges, branches, phis, declarations)
  int texture_fetches = 0;    ///< image samples, fetches and gathers
  int buffer_loads = 0;       ///< loads from uniform and storage buffers
  int transcendentals = 0;    ///< sin, cos, tan, their inverses, exp, log, pow, sqrt, inversesqrt
  int branches = 0;           ///< conditional branches and switches
  int loops = 0;              ///< loops left after unrolling
  /// Accesses into a Function or Private array with an index that is not a constant, by the
  /// array's description ("float[3] in function", "vec3[6] gPolygon"): local memory on a GPU.
  std::map<std::string, int> dynamic_local_arrays;
  int dynamically_indexed_vectors = 0;  ///< OpVectorExtract/InsertDynamic: selects on a GPU

  [[nodiscard]] int dynamic_local_array_accesses() const;
};

/// The counts of a module (already optimised as shader_stats/spirv_optimiser.hpp does).
ShaderStatistics count_shader_statistics(const SpirvModule& module);

/// A GLSL stage compiled (glslang), optimised and unrolled (SPIRV-Tools), then counted.
ShaderStatistics shader_statistics_of(const std::string& glsl, bool fragment = true);

}  // namespace glintlab
