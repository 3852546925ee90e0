#pragma once
// The shaders' integer hashes (shaders/core/sampling.glsl) in C++, bit for bit, for what the host
// and the GPU must draw alike (where a Wang tile lies: scene/normal_maps/wang_tiles.hpp).
#include <cstdint>

namespace glintlab {

/// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"): GLSL's pcgHash.
constexpr std::uint32_t pcg_hash(std::uint32_t v) {
  const std::uint32_t state = v * 747796405U + 2891336453U;
  const std::uint32_t word = ((state >> ((state >> 28U) + 4U)) ^ state) * 277803737U;
  return (word >> 22U) ^ word;
}

/// GLSL's hash3(uvec3(x, y, z)).
constexpr std::uint32_t hash3(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return pcg_hash(x ^ pcg_hash(y ^ pcg_hash(z)));
}

}  // namespace glintlab
