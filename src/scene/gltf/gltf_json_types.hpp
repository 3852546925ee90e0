#pragma once
// tinygltf keeps a property's default when its JSON has the wrong type (a baseColorFactor of "red"
// is white, silently). Before tinygltf parses a document, this check names every property glintlab
// reads whose value has the wrong type, with its path and what is allowed.
#include <span>
#include <string>
#include <string_view>

namespace glintlab::gltf {

/// The JSON of a .gltf file or of a GLB's JSON chunk (bytes that are neither are left to tinygltf,
/// which reports them). Throws InputError "FILE: materials[2].pbrMetallicRoughness.baseColorFactor
/// is "red"; allowed: an array of 4 numbers".
void check_json_types(std::span<const unsigned char> bytes, const std::string& file);

}  // namespace glintlab::gltf
