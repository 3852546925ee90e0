#pragma once
// The keys of a material's `normal_map` table (docs/scene-format.md, "Normal maps"): a file or a
// generator and its parameters.
#include <filesystem>
#include <memory>

#include "scene/normal_maps/normal_map.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

/// The map a `normal_map` table describes; relative files resolve against `base_dir`.
std::shared_ptr<const NormalMap> parse_normal_map(TomlReader r, const std::filesystem::path& base_dir);

}  // namespace glintlab
