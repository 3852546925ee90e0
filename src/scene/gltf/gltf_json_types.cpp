#include "scene/gltf/gltf_json_types.hpp"

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace glintlab::gltf {

namespace {

using nlohmann::json;

enum class Type { number, integer, boolean, string, numbers2, numbers3, numbers4, numbers16 };

const char* allowed(Type t) {
  switch (t) {
    case Type::number: return "a number";
    case Type::integer: return "an integer";
    case Type::boolean: return "true or false";
    case Type::string: return "a string";
    case Type::numbers2: return "an array of 2 numbers";
    case Type::numbers3: return "an array of 3 numbers";
    case Type::numbers4: return "an array of 4 numbers";
    case Type::numbers16: return "an array of 16 numbers";
  }
  return "";
}

bool numbers(const json& v, std::size_t n) {
  if (!v.is_array() || v.size() != n) return false;
  for (const json& x : v)
    if (!x.is_number()) return false;
  return true;
}

bool has_type(const json& v, Type t) {
  switch (t) {
    case Type::number: return v.is_number();
    case Type::integer: return v.is_number_integer();
    case Type::boolean: return v.is_boolean();
    case Type::string: return v.is_string();
    case Type::numbers2: return numbers(v, 2);
    case Type::numbers3: return numbers(v, 3);
    case Type::numbers4: return numbers(v, 4);
    case Type::numbers16: return numbers(v, 16);
  }
  return false;
}

struct Property {
  const char* key;
  Type type;
};

class Checker {
 public:
  explicit Checker(std::string file) : file_(std::move(file)) {}

  /// The properties `props` of `object` (when present), at `path`.
  void object(const json& object, const std::string& path, std::initializer_list<Property> props) const {
    if (!object.is_object()) fail(path, object, "an object");
    for (const Property& p : props)
      if (const auto it = object.find(p.key); it != object.end() && !has_type(*it, p.type))
        fail(path + "." + p.key, *it, allowed(p.type));
  }
  /// A textureInfo (glTF 2.0, 5.28): its index and texCoord, and KHR_texture_transform's values.
  void texture_info(const json& parent, const char* key, const std::string& path) const {
    const auto it = parent.find(key);
    if (it == parent.end()) return;
    const std::string at = path + "." + key;
    object(*it, at, {{"index", Type::integer}, {"texCoord", Type::integer}, {"scale", Type::number},
                     {"strength", Type::number}});
    if (const auto ext = it->find("extensions"); ext != it->end() && ext->is_object())
      if (const auto t = ext->find("KHR_texture_transform"); t != ext->end())
        object(*t, at + ".extensions.KHR_texture_transform",
               {{"offset", Type::numbers2}, {"rotation", Type::number}, {"scale", Type::numbers2},
                {"texCoord", Type::integer}});
  }
  /// Every element of the array `key` of the document, checked by `each`.
  template <typename Each>
  void each(const json& doc, const char* key, Each&& check) const {
    const auto it = doc.find(key);
    if (it == doc.end()) return;
    if (!it->is_array()) fail(key, *it, "an array");
    for (std::size_t i = 0; i < it->size(); ++i) check((*it)[i], std::string(key) + "[" + std::to_string(i) + "]");
  }

 private:
  [[noreturn]] void fail(const std::string& path, const json& value, const char* what) const {
    std::string shown = value.dump(-1, ' ', false, json::error_handler_t::replace);
    if (shown.size() > 40) shown = shown.substr(0, 40) + "...";
    throw InputError(file_ + ": " + path + " is " + shown + "; allowed: " + what);
  }
  std::string file_;
};

/// The JSON text of a .gltf, or of a GLB's first chunk (glTF 2.0, 4.4); empty if neither.
std::string_view json_text(std::span<const unsigned char> bytes) {
  const auto* text = reinterpret_cast<const char*>(bytes.data());
  if (bytes.size() < 20 || std::memcmp(text, "glTF", 4) != 0) return {text, bytes.size()};
  std::uint32_t length = 0;
  std::memcpy(&length, text + 12, 4);
  if (std::memcmp(text + 16, "JSON", 4) != 0 || length > bytes.size() - 20) return {};
  return {text + 20, length};
}

}  // namespace

void check_json_types(std::span<const unsigned char> bytes, const std::string& file) {
  const std::string_view text = json_text(bytes);
  const json doc = json::parse(text.begin(), text.end(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return;  // tinygltf names the syntax error
  const Checker c(file);
  c.each(doc, "materials", [&](const json& m, const std::string& at) {
    c.object(m, at, {{"emissiveFactor", Type::numbers3}, {"alphaCutoff", Type::number}, {"doubleSided", Type::boolean},
                     {"alphaMode", Type::string}, {"name", Type::string}});
    if (const auto pbr = m.find("pbrMetallicRoughness"); pbr != m.end()) {
      c.object(*pbr, at + ".pbrMetallicRoughness",
               {{"baseColorFactor", Type::numbers4}, {"metallicFactor", Type::number}, {"roughnessFactor", Type::number}});
      c.texture_info(*pbr, "baseColorTexture", at + ".pbrMetallicRoughness");
      c.texture_info(*pbr, "metallicRoughnessTexture", at + ".pbrMetallicRoughness");
    }
    for (const char* t : {"normalTexture", "occlusionTexture", "emissiveTexture"}) c.texture_info(m, t, at);
  });
  c.each(doc, "textures", [&](const json& t, const std::string& at) {
    c.object(t, at, {{"sampler", Type::integer}, {"source", Type::integer}});
  });
  c.each(doc, "nodes", [&](const json& n, const std::string& at) {
    c.object(n, at, {{"mesh", Type::integer}, {"camera", Type::integer}, {"translation", Type::numbers3},
                     {"rotation", Type::numbers4}, {"scale", Type::numbers3}, {"matrix", Type::numbers16}});
  });
}

}  // namespace glintlab::gltf
