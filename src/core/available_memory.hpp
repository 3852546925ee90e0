#pragma once
// How much memory a run may use, and the per-texel cost of a normal map, shared by the run's
// estimate (eval/memory_budget.hpp) and the checks that must come before an allocation, such as a
// normal-map generator's, which runs while the scene is parsed.
#include <cstdint>
#include <optional>
#include <string>

namespace glintlab {

/// A normal map's upload: a staging copy and the GPU's three mipmapped float textures (normals,
/// slope moments and their cross moment): 36 bytes a texel, 48 for the mips and staging.
inline constexpr std::uint64_t kNormalMapTexelUploadBytes = 36 + 48;

/// The environment's GLINTLAB_MEMORY_MIB when set, else the least of /proc/meminfo's MemAvailable
/// and the cgroup's limit less its usage; nullopt when unknown. Throws InputError for a malformed
/// GLINTLAB_MEMORY_MIB.
std::optional<std::uint64_t> available_memory();

/// "1.50 GiB", "12.0 MiB": sizes in messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace glintlab
