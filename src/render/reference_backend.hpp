#pragma once
// Ground truth behind one interface. A reference backend renders independent passes of jittered
// sub-pixels of the scene as it is (no filtered textures); render_reference() averages them into a
// ReferenceFrame with its own error. Backends are chosen by id (`--reference-backend`), and the id
// is part of every reference cache key, so two backends never share a cached frame.
// Adding a backend: docs/extending.md, "A ground-truth backend".
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

#include "render/pixel_filter.hpp"
#include "render/reference_estimate.hpp"
#include "scene/camera.hpp"

namespace glintlab {

class GpuScene;
class Renderer;
class ShaderLibrary;

/// A rectangle of the film in pixels from its top-left corner (y down): the part of a reference one
/// job renders when a frame is split into tiles (`render --tile`). Empty (the default): the whole film.
struct FilmRegion {
  int x = 0, y = 0, width = 0, height = 0;

  [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
  /// This region, or the whole width x height film when empty.
  [[nodiscard]] FilmRegion within(int film_width, int film_height) const;
  /// Tile `index` (row-major) of a columns x rows grid over the film, the film's pixels split as
  /// evenly as whole pixels allow.
  static FilmRegion grid_tile(int film_width, int film_height, int columns, int rows, int index);
  bool operator==(const FilmRegion&) const = default;
};

/// How a reference is sampled: `spp` samples per pixel in all, rendered as passes() independent
/// passes of k x k jittered sub-pixels (k = subpixels()), each reduced to pixels by `filter`.
struct ReferenceSettings {
  int spp = 64;            ///< passes x k x k; see subpixels()
  int light_samples = 0;   ///< per sub-pixel and light with extent; 0: max(1, ceil(256 / spp))
  int seed = 0;            ///< decorrelates frames of an animation
  PixelFilter filter;      ///< --reference-filter; default: the box of each pixel's own samples
  FilmRegion region;       ///< the pixels rendered (--tile); empty: the whole film. A pixel's samples
                           ///< do not depend on the region: tiles put together are the whole frame.
  int max_depth = 1;       ///< --max-depth: path vertices lit (1: direct light); backends that bounce
  /// k: the largest k <= 32 with k * k dividing spp and at most spp / 4 (so that there are at
  /// least four passes to estimate the reference's own error from), or 1.
  [[nodiscard]] int subpixels() const;
  [[nodiscard]] int passes() const { return spp / (subpixels() * subpixels()); }
  [[nodiscard]] int effective_light_samples() const;
};

constexpr int kMaxReferenceSpp = 65536;
constexpr int kMaxPathDepth = 64;
/// Throws InputError unless spp is in 1 .. kMaxReferenceSpp.
void validate_spp(int spp);
/// The sample seed and the sub-pixel jitter in [0, 1)^2 of one pass of a frame's reference.
std::uint32_t reference_pass_seed(int frame_seed, int pass);
glm::vec2 reference_pass_jitter(int frame_seed, int pass);

/// One pass: k x k sub-pixels per pixel, every sub-pixel moved by the same `jitter` in [0, 1)^2
/// sub-pixels from its cell's corner; `seed` selects the pass's light and BRDF samples; `filter`
/// turns the samples into pixels.
struct ReferencePass {
  int subpixels = 1;
  int light_samples = 1;
  std::uint32_t seed = 0;
  glm::vec2 jitter{0.5f};
  PixelFilter filter;
  FilmRegion region;  ///< the pixels to render; empty: the whole film
  int max_depth = 1;  ///< path vertices lit (the path backend; 1: direct light)

  /// Pass `index` of a frame's reference sampled with `settings`.
  static ReferencePass of(const ReferenceSettings& settings, int index);
};

/// Called as work is done: (units done, units total).
using ProgressFn = std::function<void(int, int)>;

class ReferenceBackend {
 public:
  virtual ~ReferenceBackend() = default;
  /// The backend's id, as `--reference-backend` takes it; part of every reference cache key.
  [[nodiscard]] virtual std::string id() const = 0;
  /// Hash of the estimator's own code on this scene (its programs' full text, or a version):
  /// a cached reference is reused only while it is unchanged.
  [[nodiscard]] virtual std::uint64_t estimator_hash() const = 0;
  /// One pass of the scene seen by `camera` on a width x height film, i.i.d. across seeds: the
  /// pixels of pass.region (the whole film when empty), each as the whole film's pass has it.
  virtual Frame render_pass(const Camera& camera, int width, int height, const ReferencePass& pass,
                            const ProgressFn& progress = {}) = 0;
};

/// Ground truth (docs/methods.md, "Ground truth"): settings.passes() passes of `backend`, their
/// mean and standard error, over settings.region of the film.
ReferenceFrame render_reference(ReferenceBackend& backend, const Camera& camera, int width, int height,
                                const ReferenceSettings& settings, const ProgressFn& progress = {});

/// What a backend is built from: the scene on the GPU and the renderer sharing its programs.
struct ReferenceBackendContext {
  ShaderLibrary& shaders;
  const GpuScene& scene;
  Renderer& renderer;
};

/// The registered backends, in the order `glintlab info` lists them; the first is the default of
/// `--reference-backend` (CommonOptions::reference_backend).
struct ReferenceBackendEntry {
  std::string id;
  std::string description;
  std::function<std::unique_ptr<ReferenceBackend>(const ReferenceBackendContext&)> create;
  /// Whether it evaluates the surface itself (every registered backend), so that it may judge
  /// methods; a backend made from a method renders that method's approximation and may not.
  bool ground_truth = true;
};
const std::vector<ReferenceBackendEntry>& reference_backends();
/// Backends made from a method: "path:<method>" or "path:<method>{name=value,...}" is the path
/// tracer with normal-map-glints materials as that method's footprint NDF, for the methods that
/// give one (MethodDescriptor::path_footprint_ndf: yan2016, deng2022): their appearance rendered
/// offline, as Deng et al. 2022 render theirs (docs/methods.md, "Methods in the path tracer").
inline constexpr const char* kPathMethodPrefix = "path:";
/// The entry of backend `id` (registered, or made from a method); throws InputError naming the id
/// and what is allowed.
ReferenceBackendEntry find_reference_backend(const std::string& id);
/// Throws InputError unless backend `id` is a ground truth: `command` (compare, animate, view)
/// judges methods against it, and a method's own approximation cannot judge one.
void require_ground_truth_backend(const std::string& id, const std::string& command);
/// find_reference_backend(id).create(context).
std::unique_ptr<ReferenceBackend> make_reference_backend(const std::string& id, const ReferenceBackendContext& context);

}  // namespace glintlab
