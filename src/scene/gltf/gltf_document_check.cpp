#include "scene/gltf/gltf_document_check.hpp"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>

#include "core/error.hpp"

namespace glintlab::gltf {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError("glTF document: " + where + ": " + what);
}

std::string name_of(const char* kind, std::size_t index) { return std::string(kind) + " " + std::to_string(index); }

void check_index(const std::string& where, const char* what, int index, std::size_t count, bool optional = true) {
  if ((optional && index == -1) || (index >= 0 && static_cast<std::size_t>(index) < count)) return;
  fail(where, std::string(what) + " " + std::to_string(index) + " out of range (" + std::to_string(count) + ")");
}

void check_range(const std::string& where, const char* what, float value, float lo, float hi) {
  if (value >= lo && value <= hi) return;  // false for NaN too
  fail(where, std::string(what) + " " + std::to_string(value) + " outside [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
}

template <typename Vec>
void check_finite(const std::string& where, const char* what, const std::vector<Vec>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < Vec::length(); ++c)
      if (!std::isfinite(values[i][c])) fail(where, std::string(what) + " " + std::to_string(i) + " is not finite");
}

void check_material(const MaterialDesc& m, const std::string& where, std::size_t images) {
  for (const TextureRef* t : {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
                              &m.emissive_texture})
    check_index(where, "image", t->image, images);
  for (int c = 0; c < 4; ++c) check_range(where, "baseColorFactor", m.base_color[c], 0.0f, 1.0f);
  for (int c = 0; c < 3; ++c) check_range(where, "emissiveFactor", m.emissive[c], 0.0f, 1.0f);
  check_range(where, "metallicFactor", m.metallic, 0.0f, 1.0f);
  check_range(where, "roughnessFactor", m.roughness, 0.0f, 1.0f);
  check_range(where, "normal scale", m.normal_scale, -1e6f, 1e6f);
  if (m.emissive_strength) check_range(where, "emissiveStrength", *m.emissive_strength, 0.0f, 1e9f);
  if (m.anisotropy) {
    check_range(where, "anisotropyStrength", m.anisotropy->x, 0.0f, 1.0f);
    check_range(where, "anisotropyRotation", m.anisotropy->y, -1e6f, 1e6f);
  }
  if (m.ior && *m.ior != 0.0f) check_range(where, "ior", *m.ior, 1.0f, 1e6f);  // 0: the 'ideal' ior of the spec
  if (m.specular) {
    check_range(where, "specularFactor", m.specular->first, 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c) check_range(where, "specularColorFactor", m.specular->second[c], 0.0f, 1e6f);
  }
}

void check_primitive(const PrimitiveDesc& p, const std::string& where, std::size_t materials) {
  const auto n = p.positions.size();
  if (n == 0) fail(where, "no positions");
  if (!p.normals.empty() && p.normals.size() != n) fail(where, "normal count differs from the position count");
  if (!p.uvs.empty() && p.uvs.size() != n) fail(where, "uv count differs from the position count");
  if (!p.tangents.empty() && p.tangents.size() != n) fail(where, "tangent count differs from the position count");
  if (!p.tangents.empty() && p.normals.empty()) fail(where, "TANGENT needs NORMAL");
  if (p.indices.empty() || p.indices.size() % 3 != 0)
    fail(where, "index count " + std::to_string(p.indices.size()) + " is not a positive multiple of 3");
  for (auto i : p.indices)
    if (i >= n || i == 0xffffffffu)
      fail(where, "index " + std::to_string(i) + " out of range (" + std::to_string(n) + " vertices)");
  check_finite(where, "position", p.positions);
  check_finite(where, "normal", p.normals);
  check_finite(where, "uv", p.uvs);
  check_finite(where, "tangent", p.tangents);
  for (std::size_t i = 0; i < p.tangents.size(); ++i)  // 3.7.2.1: w is a sign
    if (std::abs(p.tangents[i].w) != 1.0f) fail(where, "tangent " + std::to_string(i) + " has w other than +-1");
  check_index(where, "material", p.material, materials);
}

void check_light(const LightDesc& l, const std::string& where) {
  if (l.type != "directional" && l.type != "point" && l.type != "spot")
    fail(where, "type '" + l.type + "' is not directional, point or spot");
  for (int c = 0; c < 3; ++c) check_range(where, "color", l.colour[c], 0.0f, 1.0f);
  check_range(where, "intensity", l.intensity, 0.0f, 1e12f);
  if (l.range && !(*l.range > 0.0f && std::isfinite(*l.range))) fail(where, "range must be positive");
  if (l.type == "spot") {
    check_range(where, "outerConeAngle", l.outer_cone, 0.0f, glm::half_pi<float>());
    check_range(where, "innerConeAngle", l.inner_cone, 0.0f, l.outer_cone);
    if (!(l.inner_cone < l.outer_cone)) fail(where, "innerConeAngle must be below outerConeAngle");
  }
}

void check_camera(const CameraDesc& c, const std::string& where) {
  if (c.perspective) {
    check_range(where, "yfov", c.yfov, 1e-6f, glm::pi<float>() - 1e-6f);
    check_range(where, "aspectRatio", c.aspect, 0.0f, 1e6f);
    check_range(where, "znear", c.znear, 1e-9f, 1e12f);
  } else {
    if (!(c.xmag != 0.0f && c.ymag != 0.0f && std::isfinite(c.xmag) && std::isfinite(c.ymag)))
      fail(where, "xmag and ymag must be finite and non-zero");
    check_range(where, "znear", c.znear, 0.0f, 1e12f);
  }
  if (!(c.zfar > c.znear && std::isfinite(c.zfar))) fail(where, "zfar must be finite and above znear");
}

/// 3.5.3: nodes form disjoint strict trees; a scene lists roots only.
void check_hierarchy(const Document& doc) {
  const auto count = doc.nodes.size();
  std::vector<int> parent(count, -1);
  for (std::size_t i = 0; i < count; ++i)
    for (int child : doc.nodes[i].children) {
      const auto where = name_of("node", i);
      check_index(where, "child", child, count, false);
      if (parent[static_cast<std::size_t>(child)] != -1)
        fail(where, "child " + std::to_string(child) + " already has parent " +
                        std::to_string(parent[static_cast<std::size_t>(child)]));
      parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
    }
  for (std::size_t i = 0; i < count; ++i) {  // a cycle has no root: walking up never ends
    std::size_t steps = 0;
    for (int p = parent[i]; p != -1; p = parent[static_cast<std::size_t>(p)])
      if (++steps > count) fail(name_of("node", i), "is part of a cycle");
  }
  for (int root : doc.scene_nodes) {
    check_index("scene", "node", root, count, false);
    if (parent[static_cast<std::size_t>(root)] != -1) fail("scene", "node " + std::to_string(root) + " is not a root");
  }
}

void check_node(const NodeDesc& n, const std::string& where, const Document& doc) {
  check_index(where, "mesh", n.mesh, doc.meshes.size());
  check_index(where, "light", n.light, doc.lights.size());
  check_index(where, "camera", n.camera, doc.cameras.size());
  const glm::quat& q = n.rotation;
  const float length2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (!(std::abs(length2 - 1.0f) < 1e-4f)) fail(where, "rotation is not a unit quaternion");
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(n.translation[c]) || !std::isfinite(n.scale[c]))
      fail(where, "translation and scale must be finite");
}

}  // namespace

void check_document(const Document& doc) {
  for (std::size_t i = 0; i < doc.images.size(); ++i) {
    const Image8& image = doc.images[i];
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
      fail(name_of("image", i), "needs width, height > 0 and width*height*4 bytes");
  }
  for (std::size_t i = 0; i < doc.materials.size(); ++i)
    check_material(doc.materials[i], name_of("material", i), doc.images.size());
  for (std::size_t i = 0; i < doc.meshes.size(); ++i) {
    if (doc.meshes[i].primitives.empty()) fail(name_of("mesh", i), "has no primitives");
    for (std::size_t j = 0; j < doc.meshes[i].primitives.size(); ++j)
      check_primitive(doc.meshes[i].primitives[j], name_of("mesh", i) + " " + name_of("primitive", j),
                      doc.materials.size());
  }
  for (std::size_t i = 0; i < doc.lights.size(); ++i) check_light(doc.lights[i], name_of("light", i));
  for (std::size_t i = 0; i < doc.cameras.size(); ++i) check_camera(doc.cameras[i], name_of("camera", i));
  for (std::size_t i = 0; i < doc.nodes.size(); ++i) check_node(doc.nodes[i], name_of("node", i), doc);
  check_hierarchy(doc);
}

}  // namespace glintlab::gltf
