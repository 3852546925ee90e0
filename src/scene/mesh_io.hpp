#pragma once
// Mesh files as one mesh: Wavefront OBJ (its materials ignored: the scene file assigns one), and
// glTF 2.0 (.gltf, .glb) flattened (node transforms applied). Scenes import glTF files whole,
// materials, lights and cameras included, through scene/gltf/gltf_import.hpp.
#include <filesystem>

#include "scene/mesh.hpp"

namespace glintlab {

/// Throws InputError naming the file when it is missing, malformed or has no triangles.
Mesh load_mesh_file(const std::filesystem::path& path);

}  // namespace glintlab
