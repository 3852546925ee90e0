#pragma once
// Loading scenes: TOML scene files (docs/scene-format.md) and built-in scenes ("builtin:NAME").
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace glintlab {

/// `spec` is "builtin:NAME" or a path to a .toml file. Throws InputError on any bad input.
Scene load_scene(const std::string& spec);

/// Parses scene TOML text; `file` names it in messages, relative paths resolve against `base_dir`.
Scene parse_scene(std::string_view text, const std::string& file, const std::filesystem::path& base_dir);

struct BuiltinScene {
  std::string name;
  std::string description;
};
/// The built-in scenes; the first is the default.
const std::vector<BuiltinScene>& builtin_scenes();
/// TOML text of a built-in scene. Throws InputError for an unknown name, listing the known ones.
std::string builtin_scene_toml(const std::string& name);

inline constexpr const char* kDefaultScene = "builtin:every-family";

}  // namespace glintlab
