#pragma once
// Scenes for tests, written in C++ instead of pasted TOML. TestScene emits scene-format TOML
// (docs/scene-format.md) one table at a time, so a test names only what its scene is about and
// the text still goes through the parser like a user's file:
//
//   TestScene().film(32, 32).top_down_camera()
//       .material("white", {{"f0", 0}, {"diffuse", 0.5}})
//       .plane("white", {{"size", 2}})
//       .point_light({0.3, 1.0, 0.2}, 2.0)
//
// Keys a builder method does not name go in its list of extra keys; table() and raw() write
// anything else (tests of the parser's messages).
#include <charconv>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_loader.hpp"

namespace glintlab::test {

class TomlValue;
/// Keys of one table, in order.
using TomlKeys = std::vector<std::pair<std::string, TomlValue>>;

/// One TOML value: a number, a string, a boolean, an array of numbers or an inline table. Numbers
/// are written exactly (shortest round-trip form), so a float parses back to itself.
class TomlValue {
 public:
  TomlValue(int v) : text_(std::to_string(v)) {}
  TomlValue(double v) : text_(number(v)) {}
  TomlValue(bool v) : text_(v ? "true" : "false") {}
  TomlValue(const char* s) : text_(quote(s)) {}
  TomlValue(const std::string& s) : text_(quote(s)) {}
  TomlValue(std::initializer_list<double> v) : text_(array(v.begin(), v.end())) {}
  TomlValue(glm::vec2 v) : TomlValue({double(v.x), double(v.y)}) {}
  TomlValue(glm::vec3 v) : TomlValue({double(v.x), double(v.y), double(v.z)}) {}
  TomlValue(const std::vector<glm::vec3>& points) {
    text_ = "[";
    for (std::size_t i = 0; i < points.size(); ++i) text_ += (i ? ", " : "") + TomlValue(points[i]).text();
    text_ += "]";
  }
  /// An inline table, e.g. normal_map = { generator = "bumps", ... }.
  TomlValue(const TomlKeys& table) {
    text_ = "{ ";
    for (std::size_t i = 0; i < table.size(); ++i) text_ += (i ? ", " : "") + table[i].first + " = " + table[i].second.text();
    text_ += " }";
  }

  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  static std::string number(double v) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    return std::string(buffer, end);
  }
  static std::string quote(const std::string& s) { return "\"" + s + "\""; }
  static std::string array(const double* begin, const double* end) {
    std::string s = "[";
    for (const double* v = begin; v != end; ++v) s += (v != begin ? ", " : "") + number(*v);
    return s + "]";
  }

  std::string text_;
};

class TestScene {
 public:
  /// The smallest valid scene: material "m" with every default, a unit sphere and a point light.
  static TestScene minimal() { return TestScene().material("m").sphere("m").point_light({0, 2, 3}); }

  TestScene& film(int width, int height, TomlKeys more = {}) {
    return table("film", prepend({{"width", width}, {"height", height}}, std::move(more)));
  }
  /// A perspective camera; `fov` is the full vertical field of view in degrees.
  TestScene& camera(TomlValue position, TomlValue target, double fov, TomlKeys more = {}) {
    return table("camera", prepend({{"position", position}, {"target", target}, {"fov", fov}}, std::move(more)));
  }
  /// An orthographic camera seeing `view_height` scene units from top to bottom.
  TestScene& orthographic_camera(TomlValue position, TomlValue target, double view_height, TomlKeys more = {}) {
    return table("camera", prepend({{"type", "orthographic"}, {"position", position}, {"target", target},
                                    {"view_height", view_height}},
                                   std::move(more)));
  }
  /// Orthographic, straight down onto the xz square [-1, 1]^2: column -> +x, row -> +z.
  TestScene& top_down_camera() {
    return orthographic_camera({0, 10, 0}, {0, 0, 0}, 2, {{"up", {0, 0, -1}}, {"near", 1}, {"far", 20}});
  }

  TestScene& material(const std::string& name, TomlKeys keys = {}) {
    return array_table("material", prepend({{"name", name}}, std::move(keys)));
  }
  /// A glinty material (docs/scene-format.md, "Glinty materials").
  TestScene& glinty_material(const std::string& name, TomlKeys keys = {}) {
    return array_table("material", prepend({{"name", name}, {"type", "glinty"}}, std::move(keys)));
  }

  TestScene& shape(const std::string& type, const std::string& material, TomlKeys keys = {}) {
    return array_table("shape", prepend({{"type", type}, {"material", material}}, std::move(keys)));
  }
  TestScene& sphere(const std::string& material, TomlKeys keys = {}) { return shape("sphere", material, std::move(keys)); }
  TestScene& plane(const std::string& material, TomlKeys keys = {}) { return shape("plane", material, std::move(keys)); }

  TestScene& light(const std::string& type, TomlKeys keys) {
    return array_table("light", prepend({{"type", type}}, std::move(keys)));
  }
  TestScene& point_light(TomlValue position, TomlValue intensity = 1, TomlKeys more = {}) {
    return light("point", prepend({{"position", position}, {"intensity", intensity}}, std::move(more)));
  }
  TestScene& directional_light(TomlValue direction, TomlValue irradiance, TomlKeys more = {}) {
    return light("directional", prepend({{"direction", direction}, {"irradiance", irradiance}}, std::move(more)));
  }
  TestScene& disk_light(TomlValue position, TomlValue direction, double radius, TomlValue radiance, TomlKeys more = {}) {
    return light("disk", prepend({{"position", position}, {"direction", direction}, {"radius", radius},
                                  {"radiance", radiance}},
                                 std::move(more)));
  }
  TestScene& sphere_light(TomlValue position, double radius, TomlValue radiance, TomlKeys more = {}) {
    return light("sphere", prepend({{"position", position}, {"radius", radius}, {"radiance", radiance}}, std::move(more)));
  }

  /// [name] with `keys`.
  TestScene& table(const std::string& name, const TomlKeys& keys) { return write("[" + name + "]", keys); }
  /// [[name]] with `keys`.
  TestScene& array_table(const std::string& name, const TomlKeys& keys) { return write("[[" + name + "]]", keys); }
  /// TOML text appended as it is.
  TestScene& raw(const std::string& text) {
    text_ += text;
    return *this;
  }

  [[nodiscard]] const std::string& toml() const { return text_; }
  /// The parsed scene; relative paths in it resolve against `base_dir`.
  [[nodiscard]] Scene scene(const std::filesystem::path& base_dir = ".") const {
    return parse_scene(text_, "test.toml", base_dir);
  }

 private:
  static TomlKeys prepend(TomlKeys first, TomlKeys more) {
    first.insert(first.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    return first;
  }
  TestScene& write(const std::string& header, const TomlKeys& keys) {
    text_ += header + "\n";
    for (const auto& [key, value] : keys) text_ += key + " = " + value.text() + "\n";
    return *this;
  }

  std::string text_;
};

/// A built-in scene at a test's film size.
inline Scene builtin_scene(const std::string& name, int width, int height) {
  Scene scene = load_scene("builtin:" + name);
  scene.film.width = width;
  scene.film.height = height;
  return scene;
}

}  // namespace glintlab::test
