#pragma once
// The viewer's controls and picture, in Dear ImGui: the image fitted beside a side panel, the
// panel's controls generated from the method descriptors (a slider per parameter, a list per
// enumeration), a magnifier, frame times, and mouse/keyboard camera moves. Every change goes
// through a Viewer action, as a script's would.
#include <map>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "view/viewer.hpp"

namespace glintlab {

class ViewPanels {
 public:
  /// Draws this frame's controls and picture, and turns the user's input into actions.
  /// InputError from an action (a bad value typed in) is shown in the panel, not thrown.
  void draw(Viewer& viewer);

  /// Pins the magnifier on film pixel (x, y) at `zoom` (the scripts' `magnify`), or unpins it.
  void pin_magnifier(glm::ivec3 x_y_zoom) { pinned_ = x_y_zoom; magnifier_ = true; }
  void unpin_magnifier() { pinned_.reset(); }

 private:
  void side_panel(Viewer& viewer);
  void method_controls(Viewer& viewer, bool second_slot);
  void camera_controls(Viewer& viewer);
  void picture(Viewer& viewer);
  void magnifier(Viewer& viewer, float film_x, float film_y);
  void camera_input(Viewer& viewer);
  void keyboard_input(Viewer& viewer);

  // Where the picture is on screen this frame.
  float image_x_ = 0, image_y_ = 0, image_scale_ = 1;
  bool magnifier_ = true;
  int magnifier_zoom_ = 8;
  std::optional<glm::ivec3> pinned_;
  std::string screenshot_path_ = "out/view/screenshot.exr";
  std::string message_;
  std::map<std::string, float> editing_;  ///< slider values not applied until let go
  double last_play_step_ = 0;
};

}  // namespace glintlab
