#include "scene/mesh_io.hpp"

#include <tiny_obj_loader.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "scene/gltf/gltf_import.hpp"
#include "scene/obj_check.hpp"

namespace glintlab {

namespace {

/// A whole glTF file as one mesh: every primitive in the file's world (its node's transform
/// applied; a mirroring one flips the tangent frame's handedness).
Mesh flatten_gltf(const std::filesystem::path& path) {
  Mesh mesh;
  for (const GltfPrimitive& p : import_gltf(path).primitives) {
    Mesh part = *p.mesh;
    const glm::mat3 linear(p.transform);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
    const float handedness = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
    for (auto& v : part.positions) v = glm::vec3(p.transform * glm::vec4(v, 1.0f));
    for (auto& n : part.normals) n = glm::normalize(normal_matrix * n);
    for (auto& t : part.tangents) t = glm::vec4(glm::normalize(linear * glm::vec3(t)), t.w * handedness);
    mesh.append(part);
  }
  return mesh;
}

// tinyobjloader resolves indices without a range check; check_obj_statements has rejected every
// bad one with its line, and this repeats the check so no index can ever read past a list.
std::size_t checked_index(int index, std::size_t list_size, std::size_t components, const char* what,
                          const std::filesystem::path& path, const std::string& shape) {
  if (index < 0 || components * static_cast<std::size_t>(index) + components > list_size)
    throw InputError(path.string() + ": object '" + shape + "': a face refers to " + what + " " +
                     std::to_string(index + 1) + "; allowed: 1 to " + std::to_string(list_size / components));
  return static_cast<std::size_t>(index);
}

Mesh load_obj(const std::filesystem::path& path) {
  check_obj_statements(path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.mtl_search_path = path.parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path.string(), config))
    throw InputError(path.string() + ": cannot read OBJ: " + (reader.Error().empty() ? "unknown error" : reader.Error()));
  const auto& attrib = reader.GetAttrib();
  Mesh mesh;
  std::map<std::tuple<int, int, int>, std::uint32_t> unique;
  bool has_normals = true;
  for (const auto& shape : reader.GetShapes()) {
    for (const auto& idx : shape.mesh.indices) {
      const auto key = std::make_tuple(idx.vertex_index, idx.normal_index, idx.texcoord_index);
      auto [it, inserted] = unique.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) {
        const auto v = checked_index(idx.vertex_index, attrib.vertices.size(), 3, "position", path, shape.name);
        mesh.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
        if (idx.normal_index >= 0) {
          const auto n = checked_index(idx.normal_index, attrib.normals.size(), 3, "normal", path, shape.name);
          mesh.normals.emplace_back(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
        } else {
          has_normals = false;
          mesh.normals.emplace_back(0.0f);
        }
        if (idx.texcoord_index >= 0) {
          const auto t = checked_index(idx.texcoord_index, attrib.texcoords.size(), 2, "uv", path, shape.name);
          mesh.uvs.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
        } else {
          mesh.uvs.emplace_back(0.0f);
        }
      }
      mesh.indices.push_back(it->second);
    }
  }
  if (!has_normals) compute_normals(mesh);
  for (auto& n : mesh.normals) n = glm::dot(n, n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
  return mesh;
}

}  // namespace

Mesh load_mesh_file(const std::filesystem::path& path) {
  require_regular_file(path, "mesh file");
  const auto ext = path.extension().string();
  Mesh mesh;
  if (ext == ".gltf" || ext == ".glb") {
    mesh = flatten_gltf(path);
  } else if (ext == ".obj") {
    mesh = load_obj(path);
  } else {
    throw InputError(path.string() + ": unknown mesh extension '" + ext + "'; allowed: .gltf, .glb, .obj");
  }
  if (const auto problem = mesh.validate(); !problem.empty())
    throw InputError(path.string() + ": broken mesh: " + problem);
  if (mesh.tangents.empty()) compute_tangents(mesh);
  return mesh;
}

}  // namespace glintlab
