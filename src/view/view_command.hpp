#pragma once
// `glintlab view`: the interactive viewer (docs/viewer.md).
#include <filesystem>
#include <string>

#include "eval/session.hpp"

namespace glintlab {

struct ViewOptions {
  std::string compare = "reference";  ///< the second image of split/flip: a method id or "reference"
  std::string mode = "single";        ///< single, split or flip at the start
  int frame = 0;
  std::filesystem::path script;       ///< commands run one a frame (view_script.hpp)
  int window_width = 1280, window_height = 800;
};

/// Opens the window and runs until it is closed or the script says quit. Throws InputError
/// (exit 2) for bad options or script lines, RuntimeFailure without a display or OpenGL 4.5.
int run_view(const CommonOptions& options, const ViewOptions& view);

}  // namespace glintlab
