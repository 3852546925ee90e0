// Built-in scenes: scenes/<name>.toml, embedded at build time (cmake/EmbedScenes.cmake), so that
// `glintlab scenes --print NAME` prints the very file a user can copy and edit.
#include <toml++/toml.h>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"

namespace glintlab {

// Generated at build time: (name, TOML text) of every scenes/*.toml, in the listing's order.
const std::vector<std::pair<std::string, std::string_view>>& embedded_scenes();

const std::vector<BuiltinScene>& builtin_scenes() {
  static const std::vector<BuiltinScene> scenes = [] {
    std::vector<BuiltinScene> out;
    for (const auto& [name, text] : embedded_scenes()) {
      // Only the description is read here; load_scene checks the whole file.
      const toml::table root = toml::parse(text, "scenes/" + name + ".toml");
      out.push_back({name, root["description"].value_or(std::string())});
    }
    return out;
  }();
  return scenes;
}

std::string builtin_scene_toml(const std::string& name) {
  for (const auto& [n, text] : embedded_scenes())
    if (n == name) return std::string(text);
  std::string known;
  for (const auto& s : builtin_scenes()) known += (known.empty() ? "" : ", ") + s.name;
  throw InputError("builtin:" + name + ": no such built-in scene; allowed: " + known);
}

}  // namespace glintlab
