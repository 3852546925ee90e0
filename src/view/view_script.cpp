#include "view/view_script.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "view/script_arguments.hpp"

namespace glintlab {

namespace {

struct Verb {
  const char* name;
  int min_args, max_args;
  const char* usage;
};

// clang-format off
constexpr Verb kVerbs[] = {
    {"method", 1, 1, "method ID: show method ID (its parameters at their defaults)"},
    {"compare", 1, 1, "compare ID|reference: the second image of split and flip"},
    {"mode", 1, 1, "mode single|split|flip"},
    {"split", 1, 1, "split F: the fraction of the width showing the first method (0 .. 1)"},
    {"flip", 0, 0, "flip: show the other image of flip mode"},
    {"param", 1, 1, "param NAME=VALUE: a parameter of the first method"},
    {"compare-param", 1, 1, "compare-param NAME=VALUE: a parameter of the second method"},
    {"reset-params", 0, 0, "reset-params: the first method's parameters to their defaults"},
    {"error-overlay", 1, 2, "error-overlay on|off [OPACITY]: error maps against the reference over the methods"},
    {"frame", 1, 1, "frame N: frame N of the scene's camera path (back on the path)"},
    {"next", 0, 0, "next: the next frame of the path"},
    {"previous", 0, 0, "previous: the previous frame of the path"},
    {"play", 0, 0, "play: play the camera path"},
    {"pause", 0, 0, "pause"},
    {"orbit", 2, 2, "orbit YAW PITCH: orbit the target by degrees (leaves the path)"},
    {"dolly", 1, 1, "dolly F: move to F times the distance to the target"},
    {"fly", 3, 3, "fly X Y Z: move by metres right, up, forward"},
    {"look", 2, 2, "look YAW PITCH: turn the view by degrees"},
    {"path", 0, 0, "path: back to the scene's camera path"},
    {"exposure", 1, 1, "exposure STOPS"},
    {"bloom", 1, 1, "bloom B: star bloom strength (0 .. 1)"},
    {"continuous", 1, 1, "continuous on|off: re-render every frame (frame times)"},
    {"magnify", 1, 3, "magnify X Y ZOOM | magnify off: pin the magnifier on film pixel (X, Y)"},
    {"screenshot", 1, 1, "screenshot PATH: the first method's frame as 'glintlab render -o PATH' writes it"},
    {"window-screenshot", 1, 1, "window-screenshot FILE.png: the whole window, controls included"},
    {"wait", 1, 1, "wait N: let N frames pass"},
    {"quit", 0, 0, "quit"},
};
// clang-format on

const Verb* find_verb(const std::string& name) {
  for (const Verb& v : kVerbs)
    if (name == v.name) return &v;
  return nullptr;
}

}  // namespace

std::string script_where(const ScriptCommand& c) { return c.file.string() + ":" + std::to_string(c.line) + ": "; }

float script_number(const ScriptCommand& c, std::size_t i) {
  const std::string& text = c.args.at(i);
  try {
    std::size_t used = 0;
    const float v = std::stof(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw InputError(script_where(c) + c.verb + ": '" + text + "' is not a number; usage: " + find_verb(c.verb)->usage);
}

int script_integer(const ScriptCommand& c, std::size_t i) {
  const float v = script_number(c, i);
  // Compared before the cast: a float past int's range has no int (fuzz/fuzz_view_script.cpp).
  if (!(std::abs(v) <= 1e9f))
    throw InputError(script_where(c) + c.verb + ": '" + c.args[i] + "' is out of range; allowed: whole numbers of at most " +
                     "1000000000; usage: " + find_verb(c.verb)->usage);
  if (v != static_cast<float>(static_cast<int>(v)))
    throw InputError(script_where(c) + c.verb + ": '" + c.args[i] + "' is not a whole number; usage: " +
                     find_verb(c.verb)->usage);
  return static_cast<int>(v);
}

bool script_on_off(const ScriptCommand& c, std::size_t i) {
  if (c.args.at(i) == "on") return true;
  if (c.args.at(i) == "off") return false;
  throw InputError(script_where(c) + c.verb + ": '" + c.args[i] + "'; allowed: on, off");
}

namespace {

/// Checks what can be checked before any GL work: the words and numbers of each line.
void check(const ScriptCommand& c) {
  const std::string& v = c.verb;
  if (v == "mode" && c.args[0] != "single" && c.args[0] != "split" && c.args[0] != "flip")
    throw InputError(script_where(c) + "mode '" + c.args[0] + "'; allowed: single, split, flip");
  if ((v == "param" || v == "compare-param") && c.args[0].find('=') == std::string::npos)
    throw InputError(script_where(c) + v + " '" + c.args[0] + "': expected NAME=VALUE");
  if (v == "error-overlay" || v == "continuous") script_on_off(c, 0);
  if (v == "error-overlay" && c.args.size() == 2 && !(script_number(c, 1) >= 0.0f && script_number(c, 1) <= 1.0f))
    throw InputError(script_where(c) + "error-overlay: opacity " + c.args[1] + "; allowed: 0 .. 1");
  if (v == "magnify" && !(c.args.size() == 1 && c.args[0] == "off") && c.args.size() != 3)
    throw InputError(script_where(c) + "magnify: usage: " + find_verb(v)->usage);
  if (v == "magnify" && c.args.size() == 3) {
    for (std::size_t i = 0; i < 3; ++i) script_integer(c, i);
    if (script_integer(c, 0) < 0 || script_integer(c, 1) < 0)
      throw InputError(script_where(c) + "magnify " + c.args[0] + " " + c.args[1] + ": allowed: a film pixel, 0 or more");
    if (script_integer(c, 2) < kMinMagnifierZoom || script_integer(c, 2) > kMaxMagnifierZoom)
      throw InputError(script_where(c) + "magnify: zoom " + c.args[2] + "; allowed: " + std::to_string(kMinMagnifierZoom) +
                       " .. " + std::to_string(kMaxMagnifierZoom));
  }
  if (v == "frame" || v == "wait") script_integer(c, 0);
  if (v == "wait" && script_integer(c, 0) < 0) throw InputError(script_where(c) + "wait " + c.args[0] + ": allowed: 0 or more frames");
  if (v == "split" || v == "dolly" || v == "exposure" || v == "bloom") script_number(c, 0);
  if (v == "orbit" || v == "look") script_number(c, 0), script_number(c, 1);
  if (v == "fly") script_number(c, 0), script_number(c, 1), script_number(c, 2);
  if (v == "window-screenshot" && std::filesystem::path(c.args[0]).extension() != ".png")
    throw InputError(script_where(c) + "window-screenshot " + c.args[0] + ": allowed: a .png file name");
}

}  // namespace

std::vector<ScriptCommand> read_view_script(const std::filesystem::path& file) {
  std::istringstream in(read_regular_file(file, "--script", kMaxTextFileBytes));
  std::vector<ScriptCommand> commands;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    ScriptCommand c{file, line, {}, {}};
    if (!(words >> c.verb)) continue;
    for (std::string w; words >> w;) c.args.push_back(w);
    const Verb* verb = find_verb(c.verb);
    if (!verb) {
      std::string allowed;
      for (const Verb& v : kVerbs) allowed += (allowed.empty() ? "" : ", ") + std::string(v.name);
      throw InputError(script_where(c) + "unknown command '" + c.verb + "'; allowed: " + allowed);
    }
    if (static_cast<int>(c.args.size()) < verb->min_args || static_cast<int>(c.args.size()) > verb->max_args)
      throw InputError(script_where(c) + c.verb + " takes " +
                       (verb->min_args == verb->max_args ? std::to_string(verb->min_args)
                                                         : std::to_string(verb->min_args) + " to " + std::to_string(verb->max_args)) +
                       " argument(s), not " + std::to_string(c.args.size()) + "; usage: " + verb->usage);
    check(c);
    commands.push_back(std::move(c));
  }
  return commands;
}

std::string view_script_reference() {
  std::string text;
  for (const Verb& v : kVerbs) text += std::string("  ") + v.usage + "\n";
  return text;
}

}  // namespace glintlab
