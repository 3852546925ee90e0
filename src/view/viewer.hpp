#pragma once
// The viewer's model: which methods are shown and how, where the camera is, and the images that
// follow from that. Every frame comes from Session's renderer (Renderer::draw, then read_frame:
// what Session::render and so `glintlab render` do), is checked for NaN/Inf, and is shown through
// tonemap_for_display, the PNGs' transform. The UI (view_panels) and the script (view_script)
// change it through the same actions; it knows nothing of ImGui.
#include <optional>
#include <string>

#include "eval/session.hpp"
#include "gl/gpu_timer.hpp"
#include "gl/objects.hpp"

namespace glintlab {

enum class CompareMode { Single, Split, Flip };
/// The second image of a split or flip: another method, or the cached reference.
enum class SecondImage { Reference, Method };

struct MethodSlot {
  const MethodDescriptor* method = nullptr;
  ParamValues params;
};

struct ViewState {
  MethodSlot a, b;
  SecondImage second = SecondImage::Reference;
  CompareMode mode = CompareMode::Single;
  float split = 0.5f;
  bool showing_second = false;  ///< flip: which image is on screen
  bool error_overlay = false;   ///< each method's error map against the reference over it
  float overlay_opacity = 0.65f;
  int frame = 0;
  bool playing = false;
  std::optional<Camera> free_camera;  ///< set once the user moves off the scene's path
  float exposure = 0.0f, bloom = 0.0f;
  bool continuous = false;  ///< re-render every frame (for timing), not only on a change
};

/// A rendered frame and what drawing it took.
struct TimedFrame {
  Frame frame;
  GpuTime time;
};

class Viewer {
 public:
  /// Starts on `method` (with `params`), compared with `second` (nullptr: the reference), at
  /// `frame` of the path, with the scene's exposure and bloom.
  Viewer(Session& session, const MethodChoice& method, const MethodChoice* second, int frame);

  [[nodiscard]] const ViewState& state() const { return state_; }
  [[nodiscard]] Session& session() { return session_; }

  // Actions of the UI and of scripts. Each throws InputError naming the value and what is allowed.
  void select_method(bool second_slot, const std::string& id);
  void compare_with_reference();
  void set_param(bool second_slot, const std::string& name, const std::string& value);
  void set_param_value(bool second_slot, const std::string& name, float value);
  void reset_params(bool second_slot);
  void set_mode(CompareMode mode);
  void set_split(float split);
  void flip();
  void set_error_overlay(bool on, float opacity);
  void set_frame(int frame);
  void step_frame(int delta);  ///< wraps around the path
  void set_playing(bool playing);
  void move_camera(const Camera& camera);  ///< leaves the path
  void return_to_path();
  void set_exposure(float stops);
  void set_bloom(float bloom);
  void set_continuous(bool on);

  [[nodiscard]] Camera camera() const;
  [[nodiscard]] int frames() const { return session_.frames(); }
  /// Does the current view need the reference (compared with it, or error maps shown)?
  [[nodiscard]] bool needs_reference() const;
  /// Is the reference of the current view already at hand (rendered or in the cache)?
  [[nodiscard]] bool has_reference() const { return reference_ && reference_key_ == view_key(); }
  /// Needed, not at hand: the next update() renders it (or reads it from the cache).
  [[nodiscard]] bool reference_pending() const { return reference_pending_; }

  /// Renders what changed since the last call (everything, if continuous) and rebuilds the
  /// displayed image and its texture. May take long when the reference must be rendered.
  void update();
  [[nodiscard]] const Image& display() const { return display_; }
  [[nodiscard]] GLuint texture() const { return texture_.id(); }
  [[nodiscard]] int width() const { return session_.width(); }
  [[nodiscard]] int height() const { return session_.height(); }
  [[nodiscard]] const TimedFrame* shown(bool second_slot) const;
  [[nodiscard]] const ReferenceFrame* reference() const { return has_reference() ? &*reference_ : nullptr; }

  /// Writes the first method's current frame as `glintlab render -o PATH` would (PATH: a
  /// directory, or a .exr/.png name), plus <stem>.json: the method, its parameters, the frame,
  /// the camera and, on the path, the render command that writes the same files. Returns the
  /// EXR's path.
  std::string screenshot(const std::string& path);

 private:
  /// Everything a method's image depends on besides the method: camera, frame, film size.
  [[nodiscard]] std::string view_key() const;
  [[nodiscard]] std::string slot_key(const MethodSlot& slot) const;
  TimedFrame render_slot(const MethodSlot& slot);
  [[nodiscard]] Image display_of(const Frame& frame) const;
  MethodSlot& slot(bool second_slot) { return second_slot ? state_.b : state_.a; }
  void changed() { display_dirty_ = true; }

  Session& session_;
  ViewState state_;
  GpuTimer timer_;
  std::optional<TimedFrame> a_, b_;
  std::string a_key_, b_key_, reference_key_;
  std::optional<ReferenceFrame> reference_;
  bool display_dirty_ = true;
  bool reference_pending_ = false;
  Image display_;
  gl::Texture texture_;
  int texture_width_ = 0, texture_height_ = 0;
};

}  // namespace glintlab
