#pragma once
// Mesh files: glTF 2.0 (.gltf, .glb) and Wavefront OBJ. Whole files are merged into one mesh
// (glTF node transforms applied); materials in the files are ignored, the scene file assigns one.
#include <filesystem>

#include "scene/mesh.hpp"

namespace glintlab {

/// Throws InputError naming the file when it is missing, malformed or has no triangles.
Mesh load_mesh_file(const std::filesystem::path& path);

}  // namespace glintlab
