#pragma once
// Shared by the glTF importer's parts (gltf_import.cpp: geometry, lights, cameras;
// gltf_materials.cpp: materials and textures): the parsed file, what it is called in messages,
// and the warnings collected for the user. Internal to src/scene.
#include <tiny_gltf.h>

#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/materials/material.hpp"

namespace glintlab::gltf {

/// Largest texture side glintlab accepts (GL 4.5 guarantees 16384 on every driver).
inline constexpr int kMaxTextureSide = 16384;

struct ImportContext {
  const tinygltf::Model& model;
  std::string file;
  std::vector<std::string>& warnings;
  std::set<std::string> warned;  // each warning once per file

  void warn(const std::string& message) {
    if (warned.insert(message).second) warnings.push_back(file + ": " + message);
  }
  [[noreturn]] void fail(const std::string& message) const { throw InputError(file + ": " + message); }
};

/// A number of an extension object (or `fallback` when absent); must be finite.
double extension_number(const ImportContext& c, const tinygltf::Value& object, const char* key, double fallback,
                        const std::string& where);

/// The file's materials in glintlab's form, in the file's order.
std::vector<Material> import_materials(ImportContext& c);

}  // namespace glintlab::gltf
