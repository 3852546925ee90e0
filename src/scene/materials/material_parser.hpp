#pragma once
// The keys of a [[material]] table (docs/scene-format.md, "Materials").
#include <filesystem>
#include <map>
#include <string>

#include "scene/materials/material.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

/// One [[material]]; its normal map's file resolves against `base_dir`.
Material parse_material(TomlReader r, const std::filesystem::path& base_dir);

/// The index of the [[material]] that `value` (of `key`) names, by name; fails naming the defined ones.
int material_named(const TomlReader& r, const std::string& key, const std::string& value,
                   const std::map<std::string, int>& materials);

}  // namespace glintlab
