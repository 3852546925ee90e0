#include "view/view_command.hpp"

#include <imgui.h>

#include <optional>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "view/view_panels.hpp"
#include "view/view_script.hpp"
#include "view/viewer.hpp"
#include "view/window.hpp"

namespace glintlab {

int run_view(const CommonOptions& options, const ViewOptions& view) {
  // Everything that can be checked without a window is, first: methods, mode, script.
  const auto methods = resolve_methods(options.methods, options.params);
  if (methods.size() != 1) throw InputError("view: --method takes one method; the second image is --compare");
  std::optional<MethodChoice> second;
  if (view.compare != "reference") second = resolve_methods(view.compare, {}).front();
  if (view.mode != "single" && view.mode != "split" && view.mode != "flip")
    throw InputError("--mode " + view.mode + ": allowed: single, split, flip");
  const std::vector<ScriptCommand> script = view.script.empty() ? std::vector<ScriptCommand>{} : read_view_script(view.script);

  require_ground_truth_backend(options.reference_backend, "view");
  ViewWindow window(view.window_width, view.window_height, "glintlab view");
  // The renderer draws in the window's context: one renderer, one code path.
  Session session(options, Workload{.methods = 2, .reference = true},
                  [&] { return GlContext::adopt_current(window.platform()); });
  if (view.frame < 0 || view.frame >= session.frames())
    throw InputError("--frame " + std::to_string(view.frame) + ": allowed: 0 .. " + std::to_string(session.frames() - 1));
  Viewer viewer(session, methods.front(), second ? &*second : nullptr, view.frame);
  viewer.set_mode(view.mode == "split" ? CompareMode::Split : view.mode == "flip" ? CompareMode::Flip : CompareMode::Single);
  ViewPanels panels;

  std::size_t next = 0;
  int waiting = 0;
  while (!window.should_close()) {
    window.begin_frame();
    WindowRequest request;
    if (waiting > 0) {
      --waiting;
    } else if (next < script.size()) {
      request = run_script_command(script[next++], viewer);
      waiting = request.wait_frames;
      if (request.magnify) panels.pin_magnifier(*request.magnify);
      if (request.unpin_magnifier) panels.unpin_magnifier();
    }
    viewer.update();
    panels.draw(viewer);
    window.render_ui();
    if (request.window_screenshot) write_png(*request.window_screenshot, window.read_window());
    window.present();
    if (request.quit) window.request_close();
  }
  return 0;
}

}  // namespace glintlab
