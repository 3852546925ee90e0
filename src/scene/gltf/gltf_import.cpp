// glTF 2.0 import: parsing (tinygltf, with glintlab's own size-checked image decoder), the node
// hierarchy, primitives, KHR_lights_punctual and cameras. Materials: gltf_materials.cpp.
#include "scene/gltf/gltf_import.hpp"

#include <stb/stb_image.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>

#include "core/file_access.hpp"
#include "scene/gltf/gltf_json_types.hpp"
#include "scene/gltf/gltf_model.hpp"
#include "scene/lights/light_kind.hpp"

namespace glintlab {

namespace {

using gltf::ImportContext;

/// Extensions glintlab implements; any other in extensionsUsed is named in a warning, and any
/// other in extensionsRequired is an error (glTF 2.0, 3.12).
const std::set<std::string> kImplementedExtensions = {
    "KHR_texture_transform",     "KHR_materials_ior",       "KHR_materials_specular",
    "KHR_materials_anisotropy",  "KHR_materials_emissive_strength", "KHR_lights_punctual",
};

/// tinygltf's image callback: decodes PNG/JPEG/TGA/BMP to 4 channels of 8 or 16 bits, after
/// checking the size the header claims (a corrupt or hostile header must not allocate gigabytes).
bool decode_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
  int w = 0, h = 0, channels = 0;
  auto fail = [&](const std::string& why) {
    if (err) *err += "image " + std::to_string(index) + ": " + why + "\n";
    return false;
  };
  const std::string_view head(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(std::max(size, 0)));
  if (head.starts_with("\xabKTX 20\xbb"))
    return fail("is a KTX2 texture (KHR_texture_basisu, which glintlab does not implement); allowed: PNG, JPEG, TGA or BMP");
  if (head.size() >= 12 && head.starts_with("RIFF") && head.substr(8, 4) == "WEBP")
    return fail("is a WebP image (EXT_texture_webp, which glintlab does not implement); allowed: PNG, JPEG, TGA or BMP");
  if (!stbi_info_from_memory(bytes, size, &w, &h, &channels))
    return fail(std::string("cannot decode (") + (stbi_failure_reason() ? stbi_failure_reason() : "unknown") +
                "); allowed: PNG, JPEG, TGA or BMP");
  if (w < 1 || h < 1 || w > gltf::kMaxTextureSide || h > gltf::kMaxTextureSide)
    return fail("is " + std::to_string(w) + "x" + std::to_string(h) + "; allowed: 1 to " +
                std::to_string(gltf::kMaxTextureSide) + " texels a side");
  const bool is16 = stbi_is_16_bit_from_memory(bytes, size) != 0;
  void* data = is16 ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &w, &h, &channels, 4))
                    : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &channels, 4));
  if (!data) return fail(std::string("cannot decode (") + (stbi_failure_reason() ? stbi_failure_reason() : "unknown") + ")");
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4 * (is16 ? 2 : 1);
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = is16 ? 16 : 8;
  image->pixel_type = is16 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + n);
  stbi_image_free(data);
  return true;
}

// File access for external buffers and images: regular files only (a directory or a device named
// by a uri would read forever or fail obscurely), paths taken as written (tinygltf's default
// expands them with wordexp).
bool regular_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string path_as_written(const std::string& path, void*) { return path; }

/// Every file tinygltf opens (the glTF, its buffers and images) goes through glintlab's one rule.
bool read_for_tinygltf(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  try {
    const std::string bytes = read_regular_file(path, "", kMaxBinaryFileBytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}

bool refuse_writes(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {  // never called
  if (err) *err += "glintlab's importer writes no files\n";
  return false;
}

void configure(tinygltf::TinyGLTF& loader) {
  loader.SetImageLoader(decode_image, nullptr);
  loader.SetFsCallbacks({regular_file_exists, path_as_written, read_for_tinygltf, refuse_writes, nullptr});
}

template <typename T>
std::vector<T> read_accessor(const ImportContext& c, int index, int components, const char* attribute) {
  const auto& model = c.model;
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    c.fail(std::string(attribute) + " refers to accessor " + std::to_string(index) + "; the file has " +
           std::to_string(model.accessors.size()));
  const auto& acc = model.accessors[static_cast<std::size_t>(index)];
  const std::string where = "accessor " + std::to_string(index) + " (" + attribute + ")";
  if (acc.sparse.isSparse) c.fail(where + " is sparse; glintlab reads dense accessors");
  if (acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= model.bufferViews.size())
    c.fail(where + " has no buffer view");
  const auto& view = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) c.fail(where + ": its buffer view has no buffer");
  const auto& buf = model.buffers[static_cast<std::size_t>(view.buffer)];
  const int expected_type = components == 1 ? TINYGLTF_TYPE_SCALAR : components == 2 ? TINYGLTF_TYPE_VEC2
                            : components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
  if (acc.type != expected_type) c.fail(where + " has " + std::to_string(acc.type) + " components per element");
  const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
  if (component_size <= 0) c.fail(where + " has unknown component type " + std::to_string(acc.componentType));
  const std::size_t elem = static_cast<std::size_t>(component_size) * static_cast<std::size_t>(components);
  const int declared_stride = acc.ByteStride(view);
  if (declared_stride < 0) c.fail(where + " has an invalid byte stride");
  const std::size_t stride = declared_stride > 0 ? static_cast<std::size_t>(declared_stride) : elem;
  const std::size_t begin = view.byteOffset + acc.byteOffset;
  if (acc.count > buf.data.size() || begin > buf.data.size() ||
      (acc.count > 0 && begin + stride * (acc.count - 1) + elem > buf.data.size()))
    c.fail(where + " reads past the end of its buffer");
  std::vector<T> out(acc.count);
  for (std::size_t i = 0; i < acc.count; ++i) {
    const unsigned char* p = buf.data.data() + begin + i * stride;
    if constexpr (std::is_same_v<T, std::uint32_t>) {
      switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = *p; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t v;
          std::memcpy(&v, p, 2);
          out[i] = v;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], p, 4); break;
        default: c.fail(where + ": index component type " + std::to_string(acc.componentType) + " is not an unsigned integer");
      }
    } else {
      if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        c.fail(where + ": vertex attributes must be float (component type " + std::to_string(acc.componentType) + ")");
      std::memcpy(&out[i], p, sizeof(T));
    }
  }
  return out;
}

// An accessor's values must be finite: NaN or infinity would reach the rasteriser as holes.
template <typename Vec>
void require_finite(const ImportContext& c, const std::vector<Vec>& values, int accessor, const char* attribute) {
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int k = 0; k < Vec::length(); ++k)
      if (!std::isfinite(values[i][k]))
        c.fail("accessor " + std::to_string(accessor) + " (" + attribute + ") element " + std::to_string(i) +
               " has value " + std::to_string(values[i][k]) + "; allowed: finite numbers");
}

// A vertex attribute must give one value per POSITION.
template <typename Vec>
void require_count(const ImportContext& c, const std::vector<Vec>& values, std::size_t positions, int accessor,
                   const char* attribute) {
  if (values.size() != positions)
    c.fail("accessor " + std::to_string(accessor) + " (" + attribute + ") has " + std::to_string(values.size()) +
           " elements; allowed: " + std::to_string(positions) + ", the POSITION count");
}

/// One triangle primitive in glintlab's conventions (uv v up, tangent frame along +u and +v).
Mesh import_primitive(const ImportContext& c, const tinygltf::Primitive& prim, const std::string& where) {
  auto pos_it = prim.attributes.find("POSITION");
  if (pos_it == prim.attributes.end()) c.fail(where + " has no POSITION");
  Mesh part;
  part.positions = read_accessor<glm::vec3>(c, pos_it->second, 3, "POSITION");
  require_finite(c, part.positions, pos_it->second, "POSITION");
  if (prim.indices >= 0) {
    part.indices = read_accessor<std::uint32_t>(c, prim.indices, 1, "indices");
    for (std::size_t i = 0; i < part.indices.size(); ++i)
      if (part.indices[i] >= part.positions.size())
        c.fail("accessor " + std::to_string(prim.indices) + " (indices) element " + std::to_string(i) + " has value " +
               std::to_string(part.indices[i]) + "; allowed: 0 to " + std::to_string(part.positions.size()) +
               " - 1 (the POSITION count)");
  } else {
    for (std::uint32_t i = 0; i < part.positions.size(); ++i) part.indices.push_back(i);
  }
  if (part.indices.size() % 3 != 0)
    c.fail(where + " has " + std::to_string(part.indices.size()) + " indices; allowed: a multiple of 3 (triangles)");
  const bool has_normals = prim.attributes.contains("NORMAL");
  if (has_normals) {
    const int a = prim.attributes.at("NORMAL");
    part.normals = read_accessor<glm::vec3>(c, a, 3, "NORMAL");
    require_count(c, part.normals, part.positions.size(), a, "NORMAL");
    require_finite(c, part.normals, a, "NORMAL");
    for (auto& n : part.normals) n = glm::dot(n, n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
  } else {
    compute_normals(part);
  }
  if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
    part.uvs = read_accessor<glm::vec2>(c, it->second, 2, "TEXCOORD_0");
    require_count(c, part.uvs, part.positions.size(), it->second, "TEXCOORD_0");
    require_finite(c, part.uvs, it->second, "TEXCOORD_0");
    for (auto& uv : part.uvs) uv.y = 1.0f - uv.y;  // glintlab's v points up
  } else {
    part.uvs.assign(part.positions.size(), glm::vec2(0.0f));
  }
  // The file's tangents only with its normals (glTF 2.0, 3.7.2.1: without NORMAL, TANGENT is ignored).
  if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end() && has_normals) {
    part.tangents = read_accessor<glm::vec4>(c, it->second, 4, "TANGENT");
    require_count(c, part.tangents, part.positions.size(), it->second, "TANGENT");
    require_finite(c, part.tangents, it->second, "TANGENT");
    for (std::size_t i = 0; i < part.tangents.size(); ++i) {
      glm::vec4& t = part.tangents[i];
      const glm::vec3 xyz(t);
      // A tangent along its normal leaves the tangent frame undefined (NaN in every shader).
      const float across = glm::length(glm::cross(part.normals[i], xyz));
      if (!(across > 1e-6f * glm::length(xyz)) || !(glm::dot(xyz, xyz) > 0.0f))
        c.fail("accessor " + std::to_string(it->second) + " (TANGENT) element " + std::to_string(i) +
               " is zero or parallel to its NORMAL; allowed: a tangent across the normal");
      t = glm::vec4(glm::normalize(xyz), t.w < 0.0f ? -1.0f : 1.0f);
    }
  } else {
    compute_tangents(part);
  }
  if (const auto problem = part.validate(); !problem.empty()) c.fail(where + ": broken mesh: " + problem);
  return part;
}

glm::mat4 node_matrix(const ImportContext& c, const tinygltf::Node& node, int index) {
  auto finite = [&](const std::vector<double>& v, const char* what) {
    for (double x : v)
      if (!std::isfinite(x)) c.fail("node " + std::to_string(index) + " " + what + " has a non-finite value");
  };
  if (node.matrix.size() == 16) {
    finite(node.matrix, "matrix");
    return glm::mat4(glm::make_mat4(node.matrix.data()));
  }
  finite(node.translation, "translation");
  finite(node.rotation, "rotation");
  finite(node.scale, "scale");
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) m = glm::translate(m, glm::vec3(glm::make_vec3(node.translation.data())));
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::normalize(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                                 static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]))));
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(glm::make_vec3(node.scale.data())));
  return m;
}

class Importer {
 public:
  Importer(ImportContext& c, GltfAsset& out) : c_(c), out_(out) {}

  void run() {
    const auto& model = c_.model;
    for (const auto& e : model.extensionsRequired)
      if (!kImplementedExtensions.contains(e)) c_.fail("requires extension " + e + ", which glintlab does not implement");
    for (const auto& e : model.extensionsUsed)
      if (!kImplementedExtensions.contains(e)) c_.warn("extension " + e + " is not implemented; ignored");
    if (!model.skins.empty()) c_.warn("skins are ignored; skinned meshes are drawn in their bind pose");
    if (!model.animations.empty()) c_.warn("animations are ignored; the scene is drawn at rest");
    out_.materials = gltf::import_materials(c_);
    visited_.assign(model.nodes.size(), false);
    if (!model.scenes.empty()) {
      const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
      if (static_cast<std::size_t>(scene) >= model.scenes.size())
        c_.fail("default scene " + std::to_string(scene) + " does not exist; the file has " +
                std::to_string(model.scenes.size()));
      for (int n : model.scenes[static_cast<std::size_t>(scene)].nodes) visit(n);
    } else {
      // No scene: every root node (one no other node lists as a child).
      std::vector<bool> child(model.nodes.size(), false);
      for (const auto& n : model.nodes)
        for (int k : n.children)
          if (k >= 0 && static_cast<std::size_t>(k) < child.size()) child[static_cast<std::size_t>(k)] = true;
      for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (!child[n]) visit(static_cast<int>(n));
    }
    if (out_.primitives.empty()) c_.fail("has no triangles in its scene");
    if (default_material_ >= 0) {
      Material m;  // glTF's default: white, metallic 1, roughness 1
      m.name = "glTF default material";
      m.alpha = glm::vec2(1.0f);
      m.f0 = glm::vec3(1.0f);
      out_.materials.push_back(m);
    }
  }

 private:
  // Depth-first over the node hierarchy with an explicit stack: a chain of any depth is fine; a
  // node reached twice (a cycle, or two parents) is an error naming it.
  void visit(int root) {
    std::vector<std::pair<int, glm::mat4>> stack{{root, glm::mat4(1.0f)}};
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= c_.model.nodes.size())
        c_.fail("refers to node " + std::to_string(index) + "; the file has " + std::to_string(c_.model.nodes.size()));
      if (visited_[static_cast<std::size_t>(index)])
        c_.fail("node " + std::to_string(index) + " is reached twice (a cycle in the hierarchy, or two parents); "
                "allowed: a tree");
      visited_[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = c_.model.nodes[static_cast<std::size_t>(index)];
      const glm::mat4 world = parent * node_matrix(c_, node, index);
      if (node.mesh >= 0) add_mesh(node.mesh, world);
      if (node.camera >= 0) add_camera(node, index, world);
      if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end() && it->second.Has("light"))
        add_light(it->second.Get("light").GetNumberAsInt(), world);
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.emplace_back(*it, world);
    }
  }

  void add_mesh(int index, const glm::mat4& world) {
    if (static_cast<std::size_t>(index) >= c_.model.meshes.size())
      c_.fail("refers to mesh " + std::to_string(index) + "; the file has " + std::to_string(c_.model.meshes.size()));
    const tinygltf::Mesh& mesh = c_.model.meshes[static_cast<std::size_t>(index)];
    const std::string name = mesh.name.empty() ? "mesh" + std::to_string(index) : mesh.name;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      const std::string where = "mesh " + std::to_string(index) + " '" + name + "' primitive " + std::to_string(p);
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
        c_.warn(where + " has mode " + std::to_string(prim.mode) + " (not triangles); skipped");
        continue;
      }
      if (!prim.targets.empty()) c_.warn("morph targets are ignored; meshes are drawn with their base shape");
      auto& mesh_ptr = meshes_[{index, static_cast<int>(p)}];
      if (!mesh_ptr) mesh_ptr = std::make_shared<const Mesh>(import_primitive(c_, prim, where));
      int material = prim.material;
      if (material >= static_cast<int>(c_.model.materials.size()))
        c_.fail(where + " refers to material " + std::to_string(material) + "; the file has " +
                std::to_string(c_.model.materials.size()));
      if (material < 0) {
        default_material_ = static_cast<int>(c_.model.materials.size());
        material = default_material_;
      }
      out_.primitives.push_back({name, static_cast<int>(p), mesh_ptr, world, material});
    }
  }

  void add_camera(const tinygltf::Node& node, int index, const glm::mat4& world) {
    if (static_cast<std::size_t>(node.camera) >= c_.model.cameras.size())
      c_.fail("node " + std::to_string(index) + " refers to camera " + std::to_string(node.camera) + "; the file has " +
              std::to_string(c_.model.cameras.size()));
    const tinygltf::Camera& g = c_.model.cameras[static_cast<std::size_t>(node.camera)];
    const std::string where = "camera " + std::to_string(node.camera) + (g.name.empty() ? "" : " '" + g.name + "'");
    Camera cam;
    cam.position = glm::vec3(world[3]);
    const glm::vec3 forward = glm::vec3(world * glm::vec4(0, 0, -1, 0));
    const glm::vec3 up = glm::vec3(world * glm::vec4(0, 1, 0, 0));
    if (glm::length(forward) < 1e-12f || glm::length(glm::cross(forward, up)) < 1e-12f * glm::length(forward))
      c_.fail("node " + std::to_string(index) + " with " + where + " has a degenerate transform");
    cam.target = cam.position + glm::normalize(forward);  // a unit in front; the scene file may set its own
    cam.up = glm::normalize(up);
    double znear = 0, zfar = 0;
    if (g.type == "orthographic") {
      cam.projection = Projection::Orthographic;
      if (!(g.orthographic.ymag > 0) || !std::isfinite(g.orthographic.ymag))
        c_.fail(where + " ymag has value " + std::to_string(g.orthographic.ymag) + "; allowed: > 0");
      cam.view_height = static_cast<float>(2.0 * g.orthographic.ymag);
      znear = g.orthographic.znear;
      zfar = g.orthographic.zfar;
    } else {
      const double yfov = g.perspective.yfov;
      if (!(yfov > 0.0 && yfov < 3.1241))
        c_.fail(where + " yfov has value " + std::to_string(yfov) +
                "; allowed: more than 0 and less than 3.1241 (radians: 179 degrees)");
      cam.fov_y_degrees = static_cast<float>(glm::degrees(yfov));
      znear = g.perspective.znear;
      zfar = g.perspective.zfar;  // 0: infinite, which glintlab replaces by its default far plane
    }
    if (!(znear > 0.0) || !std::isfinite(znear)) c_.fail(where + " znear has value " + std::to_string(znear) + "; allowed: > 0");
    cam.near_plane = static_cast<float>(znear);
    if (zfar > znear && std::isfinite(zfar)) cam.far_plane = static_cast<float>(zfar);
    else cam.far_plane = std::max(cam.far_plane, 1e4f * cam.near_plane);
    out_.cameras.push_back({g.name.empty() ? "camera" + std::to_string(node.camera) : g.name, cam});
  }

  void add_light(int index, const glm::mat4& world) {
    if (index < 0 || static_cast<std::size_t>(index) >= c_.model.lights.size())
      c_.fail("a node refers to KHR_lights_punctual light " + std::to_string(index) + "; the file has " +
              std::to_string(c_.model.lights.size()));
    const tinygltf::Light& g = c_.model.lights[static_cast<std::size_t>(index)];
    const std::string where = "light " + std::to_string(index) + (g.name.empty() ? "" : " '" + g.name + "'");
    glm::vec3 colour(1.0f);
    if (!g.color.empty()) {
      if (g.color.size() != 3) c_.fail(where + " color does not have 3 numbers");
      for (int i = 0; i < 3; ++i) colour[i] = static_cast<float>(g.color[static_cast<std::size_t>(i)]);
    }
    if (!std::isfinite(g.intensity) || g.intensity < 0.0 || g.intensity > 1e9)
      c_.fail(where + " intensity has value " + std::to_string(g.intensity) + "; allowed: 0 to 1e9");
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(colour[i]) || colour[i] < 0.0f || colour[i] > 1.0f)
        c_.fail(where + " color has value " + std::to_string(colour[i]) + "; allowed: 0 to 1");
    if (g.range > 0.0) c_.warn("light ranges are ignored; lights fall off with the inverse square of distance");
    Light l;
    l.colour = colour * static_cast<float>(g.intensity);
    l.position = glm::vec3(world[3]);
    const glm::vec3 axis = glm::vec3(world * glm::vec4(0, 0, -1, 0));
    if (g.type == "point") {
      l.kind = &find_light_kind("point");
    } else if (g.type == "directional" || g.type == "spot") {
      if (glm::length(axis) < 1e-12f) c_.fail(where + "'s node has a degenerate transform");
      l.direction = glm::normalize(axis);
      if (g.type == "directional") {
        l.kind = &find_light_kind("directional");
      } else {
        // A float-written pi/2 is 90.0000025 degrees: clamp what rounding puts above the limit.
        constexpr double kHalfPi = 1.5707963267948966;
        const double inner = g.spot.innerConeAngle;
        double outer = g.spot.outerConeAngle;
        if (outer > kHalfPi && outer <= kHalfPi * (1.0 + 1e-6)) outer = kHalfPi;
        if (!(inner >= 0.0 && inner < outer && outer <= kHalfPi))
          c_.fail(where + " cone angles are " + std::to_string(inner) + " and " + std::to_string(outer) +
                  "; allowed: 0 <= innerConeAngle < outerConeAngle <= pi/2");
        l.kind = &find_light_kind("spot");
        l.inner_angle_degrees = static_cast<float>(glm::degrees(inner));
        l.outer_angle_degrees = static_cast<float>(glm::degrees(outer));
      }
    } else {
      c_.fail(where + " has type '" + g.type + "'; allowed: directional, point, spot");
    }
    out_.lights.push_back(l);
  }

  ImportContext& c_;
  GltfAsset& out_;
  std::vector<bool> visited_;
  std::map<std::pair<int, int>, std::shared_ptr<const Mesh>> meshes_;  // shared by the nodes that use a mesh
  int default_material_ = -1;
};

GltfAsset import_model(bool ok, const tinygltf::Model& model, const std::string& name, const std::string& err,
                       const std::string& warn) {
  if (!ok) {
    std::string why = err.empty() ? "unknown error" : err;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw InputError(name + ": cannot read glTF: " + why);
  }
  GltfAsset asset;
  ImportContext c{model, name, asset.warnings, {}};
  // glTF 2.0, 3.2: a loader refuses an asset whose major version it does not know.
  if (!model.asset.version.starts_with("2.") || model.asset.version.size() < 3)
    c.fail("asset version \"" + model.asset.version + "\"; allowed: 2.x (glTF 2.0)");
  if (!warn.empty()) c.warn(warn);
  Importer(c, asset).run();
  return asset;
}

}  // namespace

GltfAsset import_gltf(const std::filesystem::path& path) {
  const std::string bytes = read_regular_file(path, "glTF file", kMaxBinaryFileBytes);
  gltf::check_json_types({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, path.string());
  tinygltf::TinyGLTF loader;
  configure(loader);
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                                             : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
  return import_model(ok, model, path.string(), err, warn);
}

GltfAsset import_glb(std::span<const std::uint8_t> bytes, const std::string& name) {
  gltf::check_json_types(bytes, name);
  tinygltf::TinyGLTF loader;
  configure(loader);
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()));
  return import_model(ok, model, name, err, warn);
}

}  // namespace glintlab
