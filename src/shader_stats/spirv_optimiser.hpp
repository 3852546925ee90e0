#pragma once
// SPIR-V brought to the shape a GPU driver's compiler gives a fragment program before it
// allocates registers, so that what is left can be counted (shader_stats/shader_statistics.hpp):
// spirv-opt's performance passes (inlining, SSA, constant propagation, dead code), then every
// loop whose trip count is a constant unrolled, then the passes again to fold what unrolling made
// constant. Drivers unroll short constant-count loops on their own (NVIDIA's and Mesa's compilers
// do); a loop whose count is only known at run time (a per-pixel bound, or one kept rolled on
// purpose: docs/methods.md, "Driver profiles") stays a loop.
#include <cstdint>
#include <vector>

namespace glintlab {

/// The optimised, unrolled module. Throws RuntimeFailure with SPIRV-Tools' messages.
std::vector<std::uint32_t> optimise_as_a_driver_would(const std::vector<std::uint32_t>& words);

/// Marks every loop of `words` for unrolling (OpLoopMerge's Unroll control, DontUnroll cleared):
/// spirv-opt's unroller unrolls only loops so marked. Returns how many loops it marked.
int mark_loops_for_unrolling(std::vector<std::uint32_t>& words);

}  // namespace glintlab
