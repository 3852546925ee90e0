#pragma once
// Viewer scripts: one command a line, run one a displayed frame through the same actions as the
// controls (docs/viewer.md lists them). They make the viewer testable and its screenshots
// repeatable: `glintlab view --script FILE`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace glintlab {

class Viewer;

/// The magnifier's zooms (its slider's range, and `magnify X Y ZOOM`'s).
inline constexpr int kMinMagnifierZoom = 2;
inline constexpr int kMaxMagnifierZoom = 32;

struct ScriptCommand {
  std::filesystem::path file;
  int line = 0;
  std::string verb;
  std::vector<std::string> args;
};

/// Reads and checks a script (verbs, argument counts, numbers): throws InputError naming the
/// file, the line, the value and what is allowed, before the window opens.
std::vector<ScriptCommand> read_view_script(const std::filesystem::path& file);

/// What a command asks of the window rather than of the viewer.
struct WindowRequest {
  bool quit = false;
  std::optional<std::filesystem::path> window_screenshot;  ///< the whole window, controls included
  std::optional<glm::ivec3> magnify;                        ///< pin the magnifier: film x, y, zoom
  bool unpin_magnifier = false;
  int wait_frames = 0;
};

/// Runs one command on `viewer`; InputError from an action comes back naming file and line.
WindowRequest run_script_command(const ScriptCommand& command, Viewer& viewer);

/// The commands, one a line, for `glintlab view --help` and docs/viewer.md.
std::string view_script_reference();

}  // namespace glintlab
