#pragma once
// The memory a run needs, estimated before anything large is allocated, so that a film or a scene
// too large for this machine is exit 2 saying what would fit rather than std::bad_alloc half-way
// (with Mesa's llvmpipe the GPU's textures are host memory too, so they count).
#include <cstdint>
#include <optional>
#include <string>

#include "core/available_memory.hpp"  // available_memory(), format_bytes()

namespace glintlab {

struct Scene;

/// What a command holds at once.
struct Workload {
  int methods = 1;           ///< method frames held together (compare and animate hold all of them)
  bool reference = false;    ///< a reference is rendered
  bool progressive = false;  ///< --spp auto: the accumulator and a result side by side
  bool outputs = false;      ///< images, error maps and crops written (compare, animate)
  int kept_images = 0;       ///< Images kept from frame to frame (animate: each method's last error)
  std::uint64_t resources = 0;  ///< the resources its scene's kinds and methods read (estimate_resource_bytes)
};

struct MemoryEstimate {
  std::uint64_t per_pixel = 0;    ///< bytes per film pixel at the peak
  std::uint64_t film = 0;         ///< per_pixel * pixels
  std::uint64_t scene = 0;        ///< meshes, normal maps and resources, on the host and uploaded
  std::uint64_t fixed = 0;        ///< the driver, programs, tables and reference tiles
  [[nodiscard]] std::uint64_t total() const { return film + scene + fixed; }
};

/// The peak memory of `workload` on a width x height film of `scene`.
MemoryEstimate estimate_run_memory(const Workload& workload, int width, int height, const Scene& scene);

/// Throws InputError when `need` exceeds `available`, naming the film, the method count, the
/// scene's share, what it would need and what is allowed.
void require_memory(const MemoryEstimate& need, const Workload& workload, int width, int height,
                    std::uint64_t available);

}  // namespace glintlab
