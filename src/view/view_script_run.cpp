// Running a checked viewer script command on the viewer (view/view_script.hpp): the same actions
// as the controls, and what it asks of the window.
#include <cstdio>

#include "core/error.hpp"
#include "view/camera_controls.hpp"
#include "view/script_arguments.hpp"
#include "view/view_script.hpp"
#include "view/viewer.hpp"

namespace glintlab {

namespace {

WindowRequest run(const ScriptCommand& c, Viewer& viewer) {
  const std::string& v = c.verb;
  const auto& a = c.args;
  WindowRequest request;
  auto split_param = [&](const std::string& text) {
    const auto eq = text.find('=');
    return std::pair(text.substr(0, eq), text.substr(eq + 1));
  };
  if (v == "method") viewer.select_method(false, a[0]);
  else if (v == "compare") a[0] == "reference" ? viewer.compare_with_reference() : viewer.select_method(true, a[0]);
  else if (v == "mode") viewer.set_mode(a[0] == "single" ? CompareMode::Single : a[0] == "split" ? CompareMode::Split : CompareMode::Flip);
  else if (v == "split") viewer.set_split(script_number(c, 0));
  else if (v == "flip") viewer.flip();
  else if (v == "param" || v == "compare-param") {
    const auto [name, value] = split_param(a[0]);
    viewer.set_param(v == "compare-param", name, value);
  } else if (v == "reset-params") viewer.reset_params(false);
  else if (v == "error-overlay") viewer.set_error_overlay(script_on_off(c, 0), a.size() == 2 ? script_number(c, 1) : viewer.state().overlay_opacity);
  else if (v == "frame") {
    viewer.return_to_path();
    viewer.set_frame(script_integer(c, 0));
  } else if (v == "next") viewer.step_frame(1);
  else if (v == "previous") viewer.step_frame(-1);
  else if (v == "play") viewer.set_playing(true);
  else if (v == "pause") viewer.set_playing(false);
  else if (v == "orbit") viewer.move_camera(orbit_camera(viewer.camera(), script_number(c, 0), script_number(c, 1)));
  else if (v == "dolly") {
    if (script_number(c, 0) <= 0.0f) throw InputError("dolly " + a[0] + ": allowed: a factor above 0");
    viewer.move_camera(dolly_camera(viewer.camera(), script_number(c, 0)));
  } else if (v == "fly") viewer.move_camera(fly_camera(viewer.camera(), {script_number(c, 0), script_number(c, 1), script_number(c, 2)}));
  else if (v == "look") viewer.move_camera(look_camera(viewer.camera(), script_number(c, 0), script_number(c, 1)));
  else if (v == "path") viewer.return_to_path();
  else if (v == "exposure") viewer.set_exposure(script_number(c, 0));
  else if (v == "bloom") viewer.set_bloom(script_number(c, 0));
  else if (v == "continuous") viewer.set_continuous(script_on_off(c, 0));
  else if (v == "magnify") {
    if (a.size() == 1) request.unpin_magnifier = true;
    else if (script_integer(c, 0) >= viewer.width() || script_integer(c, 1) >= viewer.height())
      throw InputError("magnify " + a[0] + " " + a[1] + ": outside the film of " + std::to_string(viewer.width()) + "x" +
                       std::to_string(viewer.height()) + "; allowed: x 0 .. " + std::to_string(viewer.width() - 1) +
                       ", y 0 .. " + std::to_string(viewer.height() - 1));
    else request.magnify = glm::ivec3(script_integer(c, 0), script_integer(c, 1), script_integer(c, 2));
  } else if (v == "screenshot") {
    const std::string exr = viewer.screenshot(a[0]);
    std::printf("screenshot: %s and .png\n", exr.c_str());
  } else if (v == "window-screenshot") request.window_screenshot = a[0];
  else if (v == "wait") request.wait_frames = script_integer(c, 0);
  else if (v == "quit") request.quit = true;
  return request;
}

}  // namespace

WindowRequest run_script_command(const ScriptCommand& command, Viewer& viewer) {
  try {
    return run(command, viewer);
  } catch (const InputError& e) {
    throw InputError(script_where(command) + e.what());
  }
}

}  // namespace glintlab
