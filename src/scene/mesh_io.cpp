#include "scene/mesh_io.hpp"

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "scene/obj_check.hpp"

namespace glintlab {

namespace {

/// Smooth vertex normals (area-weighted) for meshes that come without them.
void compute_normals(Mesh& m) {
  m.normals.assign(m.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const auto a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const glm::vec3 n = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    m.normals[a] += n;
    m.normals[b] += n;
    m.normals[c] += n;
  }
  for (auto& n : m.normals) n = glm::dot(n, n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
}

template <typename T>
std::vector<T> read_accessor(const tinygltf::Model& model, int index, int components, const std::string& file) {
  const auto& acc = model.accessors.at(static_cast<std::size_t>(index));
  const auto& view = model.bufferViews.at(static_cast<std::size_t>(acc.bufferView));
  const auto& buf = model.buffers.at(static_cast<std::size_t>(view.buffer));
  const std::size_t elem = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType)) *
                           static_cast<std::size_t>(components);
  const std::size_t stride = acc.ByteStride(view) > 0 ? static_cast<std::size_t>(acc.ByteStride(view)) : elem;
  const std::size_t begin = view.byteOffset + acc.byteOffset;
  if (acc.count > buf.data.size() || begin + stride * (acc.count ? acc.count - 1 : 0) + elem > buf.data.size())
    throw InputError(file + ": accessor " + std::to_string(index) + " reads past the end of its buffer");
  std::vector<T> out(acc.count);
  for (std::size_t i = 0; i < acc.count; ++i) {
    const unsigned char* p = buf.data.data() + begin + i * stride;
    if constexpr (std::is_same_v<T, std::uint32_t>) {
      switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = *p; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: out[i] = *reinterpret_cast<const std::uint16_t*>(p); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: out[i] = *reinterpret_cast<const std::uint32_t*>(p); break;
        default: throw InputError(file + ": unsupported index component type " + std::to_string(acc.componentType));
      }
    } else {
      if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw InputError(file + ": vertex attributes must be float (component type " +
                         std::to_string(acc.componentType) + ")");
      std::memcpy(&out[i], p, sizeof(T));
    }
  }
  return out;
}

// An accessor's values must be finite: NaN or infinity would reach the rasteriser as holes.
template <typename Vec>
void require_finite(const std::vector<Vec>& values, int accessor, const char* attribute, const std::string& file) {
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < Vec::length(); ++c)
      if (!std::isfinite(values[i][c]))
        throw InputError(file + ": accessor " + std::to_string(accessor) + " (" + attribute + ") element " +
                         std::to_string(i) + " has value " + std::to_string(values[i][c]) + "; allowed: finite numbers");
}

// A vertex attribute must give one value per POSITION.
template <typename Vec>
void require_count(const std::vector<Vec>& values, std::size_t positions, int accessor, const char* attribute,
                   const std::string& file) {
  if (values.size() != positions)
    throw InputError(file + ": accessor " + std::to_string(accessor) + " (" + attribute + ") has " +
                     std::to_string(values.size()) + " elements; allowed: " + std::to_string(positions) +
                     ", the POSITION count");
}

void require_indices_in_range(const std::vector<std::uint32_t>& indices, std::size_t positions, int accessor,
                              const std::string& file) {
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= positions)
      throw InputError(file + ": accessor " + std::to_string(accessor) + " (indices) element " + std::to_string(i) +
                       " has value " + std::to_string(indices[i]) + "; allowed: 0 to " +
                       std::to_string(positions) + " - 1 (the POSITION count)");
}

glm::mat4 node_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m = glm::make_mat4(node.matrix.data());
    return glm::mat4(m);
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = glm::translate(m, glm::vec3(glm::make_vec3(node.translation.data())));
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                  static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(glm::make_vec3(node.scale.data())));
  return m;
}

void add_gltf_node(const tinygltf::Model& model, int index, const glm::mat4& parent, Mesh& out,
                   const std::string& file, int depth) {
  if (depth > 64) throw InputError(file + ": node hierarchy deeper than 64 (a cycle?)");
  const auto& node = model.nodes.at(static_cast<std::size_t>(index));
  const glm::mat4 world = parent * node_matrix(node);
  if (node.mesh >= 0) {
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(world)));
    for (const auto& prim : model.meshes.at(static_cast<std::size_t>(node.mesh)).primitives) {
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
      auto pos_it = prim.attributes.find("POSITION");
      if (pos_it == prim.attributes.end()) throw InputError(file + ": a primitive has no POSITION");
      Mesh part;
      part.positions = read_accessor<glm::vec3>(model, pos_it->second, 3, file);
      require_finite(part.positions, pos_it->second, "POSITION", file);
      if (prim.indices >= 0) {
        part.indices = read_accessor<std::uint32_t>(model, prim.indices, 1, file);
        require_indices_in_range(part.indices, part.positions.size(), prim.indices, file);
      } else {
        for (std::uint32_t i = 0; i < part.positions.size(); ++i) part.indices.push_back(i);
      }
      if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
        part.normals = read_accessor<glm::vec3>(model, it->second, 3, file);
        require_count(part.normals, part.positions.size(), it->second, "NORMAL", file);
        require_finite(part.normals, it->second, "NORMAL", file);
      } else {
        compute_normals(part);
      }
      if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
        part.uvs = read_accessor<glm::vec2>(model, it->second, 2, file);
        require_count(part.uvs, part.positions.size(), it->second, "TEXCOORD_0", file);
        require_finite(part.uvs, it->second, "TEXCOORD_0", file);
      } else {
        part.uvs.assign(part.positions.size(), glm::vec2(0.0f));
      }
      for (auto& p : part.positions) p = glm::vec3(world * glm::vec4(p, 1.0f));
      for (auto& n : part.normals) n = glm::normalize(normal_matrix * n);
      out.append(part);
    }
  }
  for (int child : node.children) add_gltf_node(model, child, world, out, file, depth + 1);
}

Mesh load_gltf(const std::filesystem::path& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = path.extension() == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                         : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
  if (!ok) throw InputError(path.string() + ": cannot read glTF: " + (err.empty() ? "unknown error" : err));
  Mesh mesh;
  try {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (!model.scenes.empty()) {
      for (int n : model.scenes.at(static_cast<std::size_t>(scene)).nodes)
        add_gltf_node(model, n, glm::mat4(1.0f), mesh, path.string(), 0);
    } else {
      for (std::size_t n = 0; n < model.nodes.size(); ++n)
        add_gltf_node(model, static_cast<int>(n), glm::mat4(1.0f), mesh, path.string(), 0);
    }
  } catch (const std::out_of_range&) {
    throw InputError(path.string() + ": glTF refers to a missing node, mesh, accessor or buffer");
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
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + ": mesh file does not exist or is not a file");
  const auto ext = path.extension().string();
  Mesh mesh;
  if (ext == ".gltf" || ext == ".glb") {
    mesh = load_gltf(path);
  } else if (ext == ".obj") {
    mesh = load_obj(path);
  } else {
    throw InputError(path.string() + ": unknown mesh extension '" + ext + "'; allowed: .gltf, .glb, .obj");
  }
  if (const auto problem = mesh.validate(); !problem.empty())
    throw InputError(path.string() + ": broken mesh: " + problem);
  compute_tangents(mesh);
  return mesh;
}

}  // namespace glintlab
