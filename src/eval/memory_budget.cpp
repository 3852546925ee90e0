#include "eval/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/available_memory.hpp"
#include "core/error.hpp"
#include "scene/scene.hpp"

namespace glintlab {

namespace {

// Bytes per film pixel of what the commands allocate. An Image is RGB float: 12. Checked against
// the peak RSS of `compare --methods all` (11 methods) on llvmpipe at 1024^2 and 2048^2: 509 bytes
// a pixel measured, 516 estimated, and 260 MiB besides.
constexpr std::uint64_t kImage = 12;
constexpr std::uint64_t kRenderTarget = 36;     // the renderer's total and specular RGBA32F, depth 32F
constexpr std::uint64_t kReadback = 16;         // one RGBA float read-back, before it becomes an Image
constexpr std::uint64_t kDriver = 32;           // the driver's own copies (measured, not itemised)
constexpr std::uint64_t kFrame = 24;            // a method's total and specular Images
constexpr std::uint64_t kAccumulator = 96;      // a reference's four double-precision RGB sums
constexpr std::uint64_t kReferencePass = 32 + 24;  // a pass's output textures and its Frame
constexpr std::uint64_t kReferenceFrame = 60;   // mean (total, specular), standard error, even and odd halves
constexpr std::uint64_t kOutputs = 80;          // error sum, one error map, displays and encoders at a time
// The driver, shader programs, tables and the reference's fixed-size high-resolution tile.
constexpr std::uint64_t kFixed = 512ull << 20;
// Scene data still to be uploaded: a staging copy and the GPU's (normal maps:
// kNormalMapTexelUploadBytes, core/available_memory.hpp).
constexpr std::uint64_t kVertexUpload = 2 * 48;
constexpr std::uint64_t kIndexUpload = 4;

}  // namespace

MemoryEstimate estimate_run_memory(const Workload& workload, int width, int height, const Scene& scene) {
  MemoryEstimate e;
  // Peak of the render phase (method frames, then the reference on top of them) and of the
  // output phase (frames and the reference's result, then the outputs one at a time).
  std::uint64_t rendering = kDriver + kRenderTarget + kReadback + workload.methods * kFrame;
  if (workload.reference)
    rendering += kAccumulator + kReferencePass + kReadback + (workload.progressive ? kReferenceFrame : 0);
  const std::uint64_t writing = kDriver + kRenderTarget + workload.methods * kFrame + (workload.reference ? kReferenceFrame : 0) +
                                (workload.outputs ? kOutputs : kFrame) + workload.kept_images * kImage;
  e.per_pixel = std::max(rendering, writing);
  e.film = e.per_pixel * static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  for (const auto& shape : scene.shapes)
    e.scene += shape.mesh->positions.size() * kVertexUpload + shape.mesh->indices.size() * kIndexUpload;
  for (const auto& m : scene.materials)  // GpuScene uploads a map once per material that has it
    if (m.normal_map) e.scene += m.normal_map->normals.size() * kNormalMapTexelUploadBytes;
  e.scene += workload.resources;
  e.fixed = kFixed;
  return e;
}

void require_memory(const MemoryEstimate& need, const Workload& workload, int width, int height,
                    std::uint64_t available) {
  if (need.total() <= available) return;
  std::ostringstream s;
  s << "film " << width << "x" << height << " with " << workload.methods << (workload.methods == 1 ? " method" : " methods")
    << (workload.reference ? " and a reference" : "") << " needs ~" << format_bytes(need.total())
    << " of memory (" << format_bytes(need.film) << " for the film at " << need.per_pixel << " bytes a pixel, "
    << format_bytes(need.scene) << " to upload the scene's meshes, normal maps and resources, " << format_bytes(need.fixed)
    << " for the driver and tables); available: " << format_bytes(available)
    << "; lower --width/--height, the method count, or the scene's mesh and normal-map resolutions"
    << " (GLINTLAB_MEMORY_MIB sets what may be used)";
  throw InputError(s.str());
}

}  // namespace glintlab
