#pragma once
// What every command needs: the GL context, the scene on the GPU, a renderer and the reference
// cache, plus the resolved command-line choices shared by all commands.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
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
  int spp = 64;
  int light_samples = 0;
  int width = 0;   ///< 0: the scene's film
  int height = 0;
  int frames = 0;  ///< 0: the scene's camera path
  std::string out;
  bool no_cache = false;
  bool quiet = false;
};

/// A method chosen on the command line with its resolved parameter values.
struct MethodChoice {
  const MethodDescriptor* method;
  ParamValues params;
};

/// Resolves --methods and --param; throws InputError for unknown methods or parameters.
std::vector<MethodChoice> resolve_methods(const std::string& methods, const std::vector<std::string>& params);

class Session {
 public:
  explicit Session(const CommonOptions& options);

  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int frames() const { return frames_; }
  [[nodiscard]] Camera camera(int frame) const { return scene_.path.at(scene_.camera, frame); }
  Renderer& renderer() { return *renderer_; }
  GlContext& context() { return *context_; }

  /// Renders a method's frame; throws RuntimeFailure if it holds NaN or Inf.
  Frame render(const MethodChoice& choice, int frame);
  /// The ground truth of a frame, from the cache when possible; throws on NaN or Inf.
  Frame reference(int frame);
  [[nodiscard]] const ReferenceSettings& reference_settings() const { return reference_; }

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
  std::uint64_t shaders_hash_ = 0;  ///< part of every reference cache key
  std::string device_;
};

/// Throws RuntimeFailure naming `what` and the number of pixels with NaN or Inf.
void require_finite(const Frame& frame, const std::string& what);

}  // namespace glintlab
