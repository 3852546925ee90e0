#pragma once
// What every command needs: the GL context, the scene on the GPU, a renderer and the reference
// cache, plus the resolved command-line choices shared by all commands.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "eval/memory_budget.hpp"
#include "shading/method_list.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/reference_backend.hpp"
#include "render/reference_cache.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// The flags every command shares (same names for the same things).
struct CommonOptions {
  std::string scene;
  std::string methods = "conventional";
  std::vector<std::string> params;  ///< "name=value" or "method.name=value"
  std::string spp_text;         ///< --spp as given; Session parses it (parse_spp)
  int spp = 64;
  bool spp_auto = false;        ///< --spp auto: progressive reference, see Session::reference
  int max_spp = 4096;           ///< the cap of --spp auto
  double noise_fraction = 0.1;  ///< --spp auto's target, a fraction of the differences ranked
  int light_samples = 0;
  int width = 0;   ///< 0: the scene's film
  int height = 0;
  int frames = 0;  ///< 0: the scene's camera path
  std::string out;
  bool no_cache = false;
  std::string reference_backend = reference_backends().front().id;  ///< --reference-backend; default: the first
  std::string reference_filter = "box";  ///< --reference-filter: box or gaussian:S (PixelFilter::parse)
  std::string tile;  ///< render --tile INDEX/COLUMNSxROWS: the reference of one tile of the film (parse_tile)
  int max_depth = 1;  ///< --max-depth: the path backend's lit path vertices (1: direct light)
  double pixels_per_degree = 0;  ///< --ppd (compare, animate): FLIP's viewing; 0: flip::default_pixels_per_degree()
  bool quiet = false;
};

class Session {
 public:
  /// `workload`: what the command holds at once, checked against the memory available before
  /// any GPU work (InputError when too large); default: every listed method's frame together,
  /// a reference and compare's outputs. `make_context` makes the GL context everything is drawn
  /// with: a headless one for the commands, the window's for the viewer (the same renderer).
  using ContextFactory = std::function<std::unique_ptr<GlContext>()>;
  explicit Session(const CommonOptions& options, std::optional<Workload> workload = std::nullopt,
                   const ContextFactory& make_context = &GlContext::create_headless);

  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int frames() const { return frames_; }
  [[nodiscard]] Camera camera(int frame) const { return scene_.path.at(scene_.camera, frame); }
  Renderer& renderer() { return *renderer_; }
  GpuScene& gpu_scene() { return *gpu_scene_; }
  ReferenceBackend& reference_backend() { return *reference_backend_; }
  GlContext& context() { return *context_; }
  /// What another backend than the session's own is made from (`converge` times several).
  ReferenceBackendContext backend_context() { return {shaders_, *gpu_scene_, *renderer_}; }

  /// Renders a method's frame; throws RuntimeFailure if it holds NaN or Inf.
  Frame render(const MethodChoice& choice, int frame);
  /// The ground truth of a frame, from the cache when possible; throws on NaN or Inf.
  /// With --spp N: N samples per pixel. With --spp auto: passes of kProgressivePassSpp are added
  /// until the reference's noise RMSE is at most noise_fraction times the smallest of the
  /// `ranked` methods' RMSEs and of their nonzero pairwise differences, or max_spp is reached.
  /// `at`: another camera than the frame's (the viewer's free camera), with the frame's seed.
  ReferenceFrame reference(int frame, const std::vector<const Frame*>& ranked = {},
                           const std::optional<Camera>& at = std::nullopt);
  /// Every method's frame, then the reference ranked by them (methods first: --spp auto sizes the
  /// reference by the differences between them; a NaN anywhere throws before anything is written).
  struct Rendered {
    std::vector<Frame> methods;
    ReferenceFrame reference;
  };
  Rendered render_with_reference(const std::vector<MethodChoice>& methods, int frame);
  [[nodiscard]] const ReferenceSettings& reference_settings() const { return reference_; }
  [[nodiscard]] const CommonOptions& options() const { return options_; }

 private:
  CommonOptions options_;
  std::unique_ptr<GlContext> context_;
  ShaderLibrary shaders_;
  Scene scene_;
  std::unique_ptr<GpuScene> gpu_scene_;
  std::unique_ptr<Renderer> renderer_;
  ReferenceCache cache_;
  ReferenceSettings reference_;
  int width_ = 0, height_ = 0, frames_ = 1;
  std::unique_ptr<ReferenceBackend> reference_backend_;
  std::string device_;
};

/// Samples per pixel of one pass of a progressive (--spp auto) reference: k = 8.
constexpr int kProgressivePassSpp = 64;

/// --spp auto's target: `fraction` times the smallest of the methods' RMSEs against `reference`
/// and of their pairwise differences larger than 1e-9 (identical methods are not a ranking).
double reference_noise_target(const Frame& reference, const std::vector<const Frame*>& ranked, double fraction);

/// Parses --tile INDEX/COLUMNSxROWS for a width x height film: tile INDEX (row-major, from 0) of
/// an even grid; throws InputError naming --tile, the value and what is allowed.
FilmRegion parse_tile(const std::string& text, int width, int height);
/// Parses --spp (or --reference=): a sample count or "auto"; throws InputError naming `flag`.
void parse_spp(const std::string& text, const std::string& flag, CommonOptions& options);

/// Throws RuntimeFailure naming `what` and the number of pixels with NaN or Inf.
void require_finite(const Frame& frame, const std::string& what);

}  // namespace glintlab
