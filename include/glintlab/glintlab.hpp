#pragma once
// glintlab as a library: open a scene, render a method or the ground truth into arrays, measure
// methods against the truth frame by frame. The installed C++ interface (`find_package(glintlab)`,
// target glintlab::glintlab; docs/library.md) and what the Python module wraps (docs/python.md).
// Only standard types cross it; what the CLI refuses (exit 2) throws InputError with the CLI's
// message, what fails at run time throws RuntimeFailure.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "glintlab/error.hpp"

namespace glintlab {

/// Linear RGB radiance, `height` rows from the top, `width` pixels a row, 3 floats a pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> pixels;
};

/// A method's frame: everything it shades, and its specular part alone.
struct Rendering {
  RgbImage total, specular;
};

/// The ground truth of a frame (docs/reference.md): the mean of its passes, the standard error of
/// each pixel's mean from their spread, and what it resolves.
struct ReferenceRendering {
  RgbImage total, specular, standard_error;
  int spp = 0, passes = 0;
  double noise_rmse = 0;  ///< the RMSE its noise is expected to have against the converged image
};

/// A parameter of a method as `glintlab methods` lists it.
struct ParameterInfo {
  std::string name, description;
  std::string default_value;  ///< as a user writes it: the number, or the choice's name
  std::string allowed;        ///< "0 .. 1", or "a|b|c" for a choice
  std::vector<std::string> choices;  ///< empty unless the parameter is a choice
};

struct MethodInfo {
  std::string id, title, citation, summary;
  std::vector<ParameterInfo> parameters;
};

/// Every registered method, in `glintlab methods`' order.
std::vector<MethodInfo> list_methods();
/// The built-in scenes' names ("builtin:spheres", ...), as `glintlab scenes` lists them.
std::vector<std::string> list_builtin_scenes();

/// Metrics by the names of compare's metrics.json ("rmse", "flip_ldr", "sparkle_distance", ...).
using Metrics = std::map<std::string, double>;

/// The choices shared by every call on a scene (the CLI's flags of the same names).
struct LabOptions {
  int width = 0, height = 0;  ///< 0: the scene's film
  int frames = 0;             ///< 0: the scene's camera path
  std::string spp = "64";     ///< the reference's samples per pixel, or "auto" (as --spp)
  std::string reference_backend;  ///< empty: the default (raster); "path", "path:<method>", ...
  std::vector<std::string> params;  ///< "name=value" or "method.name=value" (as --param)
  double pixels_per_degree = 0;     ///< FLIP's viewing; 0: the default (as --ppd)
  bool use_cache = true;            ///< false: as --no-cache (references rendered again)
  bool quiet = true;                ///< false: progress bars on stderr, as the CLI
};

/// The metrics of every method of a comparison, and what the reference's own noise scores
/// (its even passes against its odd ones: FLIP and sparkle differences below these are noise).
struct Comparison {
  std::map<std::string, Metrics> methods;
  Metrics reference;  ///< "noise_rmse", "spp", "flip_ldr_floor", "flip_hdr_floor", "sparkle_floor"
};

/// One frame of an animation: each method's frame and metrics against that frame's reference.
struct AnimationFrame {
  int frame = 0;
  std::map<std::string, Rendering> renderings;
  std::map<std::string, Metrics> metrics;  ///< "rmse", "sparkle_distance", "flip_ldr", "flip_hdr"
  ReferenceRendering reference;
};

class Lab;

/// A camera path walked frame by frame (Lab::animate). summary() holds what `glintlab animate`
/// reports over the frames stepped so far: mean_rmse, flicker, mean_sparkle_distance,
/// mean_flip_ldr, mean_flip_hdr per method, and under "reference" its flicker_floor, noise_rmse,
/// spp_min and spp_max. It renders with its Lab, which must outlive it.
class Animation {
 public:
  ~Animation();
  Animation(Animation&&) noexcept;
  Animation& operator=(Animation&&) noexcept;

  [[nodiscard]] int frames() const;
  [[nodiscard]] bool done() const;
  /// Renders the next frame; throws std::out_of_range past the last.
  AnimationFrame next();
  [[nodiscard]] std::map<std::string, Metrics> summary() const;

 private:
  friend class Lab;
  struct State;
  explicit Animation(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

/// A scene opened on a GL context of its own (headless EGL; one Lab at a time per thread).
class Lab {
 public:
  /// `scene`: a scene file (TOML or glTF) or "builtin:<name>"; throws InputError as the CLI.
  explicit Lab(const std::string& scene, const LabOptions& options = {});
  ~Lab();
  Lab(Lab&&) noexcept;
  Lab& operator=(Lab&&) noexcept;

  [[nodiscard]] int width() const;
  [[nodiscard]] int height() const;
  [[nodiscard]] int frames() const;
  [[nodiscard]] std::string scene() const;

  /// One method (an id, or a variant "id{name=value,...}") on one frame of the camera path.
  Rendering render(const std::string& method, int frame = 0);
  /// The ground truth of a frame, from the reference cache when it holds it.
  ReferenceRendering reference(int frame = 0);
  /// The methods (a list as --methods takes it, "all" included) against the reference.
  Comparison compare(const std::string& methods, int frame = 0);
  /// The camera path for the methods, frame by frame (next()).
  Animation animate(const std::string& methods);

 private:
  friend class Animation;
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace glintlab
