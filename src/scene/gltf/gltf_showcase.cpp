#include "scene/gltf/gltf_showcase.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "core/colour.hpp"

namespace glintlab::gltf {

namespace {

/// A rigidly moved copy: a rotation keeps every tangent frame's handedness, so w is unchanged.
Mesh moved(Mesh mesh, const glm::quat& rotation, glm::vec3 offset) {
  for (auto& p : mesh.positions) p = rotation * p + offset;
  for (auto& n : mesh.normals) n = rotation * n;
  for (auto& t : mesh.tangents) t = glm::vec4(rotation * glm::vec3(t), t.w);
  return mesh;
}

/// The faces of an axis-aligned cube of edge `size` around the origin, each with uv [0, 1]^2
/// upright when seen from outside: the four sides (`sides`) or the top and bottom.
Mesh make_cube_faces(float size, bool sides) {
  const Mesh face = moved(make_plane({size, size}, 1.0f, 1), glm::quat(1, 0, 0, 0), {0, size / 2, 0});
  const glm::quat stand_up = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));  // +y -> +z
  Mesh out;
  if (sides) {
    for (int k = 0; k < 4; ++k)
      out.append(moved(face, glm::angleAxis(glm::half_pi<float>() * static_cast<float>(k), glm::vec3(0, 1, 0)) * stand_up,
                       glm::vec3(0)));
  } else {
    out.append(face);
    out.append(moved(face, glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)), glm::vec3(0)));
  }
  return out;
}

// ---- Images (all in glTF uv: v down, row 0 at the top) ----

/// 8x8 checker, with the top-left tile tinted red and the top-right one green, so a flipped or
/// mirrored uv mapping is visible.
Image8 checker_image() {
  return make_image(128, 128, [](glm::vec2 uv) {
    const int i = static_cast<int>(uv.x * 8.0f), j = static_cast<int>(uv.y * 8.0f);
    glm::vec3 c = (i + j) % 2 == 0 ? glm::vec3(0.8f, 0.8f, 0.78f) : glm::vec3(0.15f, 0.17f, 0.22f);
    if (j == 0 && i == 0) c = glm::vec3(0.8f, 0.15f, 0.1f);
    if (j == 0 && i == 7) c = glm::vec3(0.1f, 0.7f, 0.15f);
    return glm::vec4(c, 1.0f);
  });
}

/// Roughness (G) in 8 steps from 0.05 to 0.8 along u; metallic (B) 1 in every other band of 16
/// rows along v; R (occlusion, unused) 1.
Image8 roughness_metal_image() {
  return make_image(128, 128, [](glm::vec2 uv) {
    const float roughness = 0.05f + 0.75f * std::floor(uv.x * 8.0f) / 7.0f;
    const float metallic = static_cast<int>(uv.y * 8.0f) % 2 == 0 ? 0.0f : 1.0f;
    return glm::vec4(1.0f, roughness, metallic, 1.0f);
  });
}

/// Golf-ball dimples on the sphere's (u, v) = (longitude, colatitude) map: 16 x 8 cells, square on
/// the equator, alternate rows staggered by half a cell. Height in cell units
/// h = -depth (1 - r^2/R^2)^2 inside radius R (smooth at the rim); normal = (-dh/dx, -dh/dy_up, 1)
/// with y_up = -v, i.e. (-dh/da, +dh/db, 1) in the cell coordinates (a right, b down).
Image8 dimple_normal_image() {
  return make_normal_image(256, 128, [](glm::vec2 uv) {
    constexpr float kRadius = 0.42f, kDepth = 0.15f;
    const float row = std::floor(uv.y * 8.0f);
    const float shift = std::fmod(row, 2.0f) * 0.5f;
    const float a = std::fmod(uv.x * 16.0f + shift, 1.0f) - 0.5f;
    const float b = uv.y * 8.0f - row - 0.5f;
    const float q = 1.0f - (a * a + b * b) / (kRadius * kRadius);
    if (q <= 0.0f) return glm::vec3(0, 0, 1);
    const float dh_da = 4.0f * kDepth * q * a / (kRadius * kRadius);
    const float dh_db = 4.0f * kDepth * q * b / (kRadius * kRadius);
    return glm::vec3(-dh_da, dh_db, 1.0f);
  });
}

/// Sinusoidal ribs running at 30 degrees to the image's vertical, so both x and y of the normal
/// vary: h = amplitude sin(2 pi k (x cos 30 + y sin 30)) with y up in the image.
Image8 rib_normal_image() {
  return make_normal_image(128, 128, [](glm::vec2 uv) {
    constexpr float kRibs = 6.0f, kAmplitude = 0.03f;
    const glm::vec2 across(std::cos(glm::radians(30.0f)), std::sin(glm::radians(30.0f)));
    const glm::vec2 p(uv.x, 1.0f - uv.y);  // x right, y up
    const float slope = kAmplitude * glm::two_pi<float>() * kRibs *
                        std::cos(glm::two_pi<float>() * kRibs * glm::dot(p, across));
    return glm::vec3(-slope * across.x, -slope * across.y, 1.0f);
  });
}

/// A glowing lattice for the lantern: bright bars along the tile edges and a ring in the middle.
Image8 lantern_emissive_image() {
  return make_image(64, 64, [](glm::vec2 uv) {
    const glm::vec2 d = glm::abs(uv - 0.5f);
    const float edge = std::max(d.x, d.y) > 0.42f ? 1.0f : 0.0f;
    const float ring = std::abs(glm::length(uv - 0.5f) - 0.25f) < 0.05f ? 0.8f : 0.0f;
    const float glow = std::max(edge, ring);
    return glm::vec4(glow, glow, glow, 1.0f);
  });
}

/// Fine streaks along u for the brushed torus (its anisotropy direction): a hash per row of
/// texels, so the streaks are sharp across v and constant along u.
Image8 brushed_image() {
  return make_image(128, 64, [](glm::vec2 uv) {
    std::uint32_t h = static_cast<std::uint32_t>(uv.y * 64.0f) * 2654435761u;
    h ^= h >> 15;
    const float streak = 0.8f + 0.2f * static_cast<float>(h % 1000u) / 999.0f;
    return glm::vec4(glm::vec3(streak), 1.0f);
  });
}

/// A node at `eye` whose -Z axis looks at `target` (glTF cameras and lights look along -Z).
glm::quat look_at(glm::vec3 eye, glm::vec3 target) {
  return glm::quatLookAtRH(glm::normalize(target - eye), glm::vec3(0, 1, 0));
}

enum Image { kChecker, kRoughnessMetal, kDimples, kRibs, kLantern, kBrushed };
enum Material { kGround, kDimpledGold, kBrushedDielectric, kLanternGlow, kRibbedPanel };

std::vector<MaterialDesc> showcase_materials() {
  std::vector<MaterialDesc> m(5);
  m[kGround].name = "checker-ground";
  m[kGround].base_color_texture = {kChecker, TextureTransform{{0.1f, 0.05f}, {3.0f, 3.0f}, 0.25f}};
  m[kGround].metallic_roughness_texture = {kRoughnessMetal, TextureTransform{{0.0f, 0.5f}, {2.0f, 2.0f}, -0.4f}};
  m[kDimpledGold].name = "dimpled-gold";
  m[kDimpledGold].base_color = {1.0f, 0.78f, 0.34f, 1.0f};
  m[kDimpledGold].roughness = 0.22f;
  m[kDimpledGold].normal_texture = {kDimples, std::nullopt};
  m[kDimpledGold].normal_scale = 0.8f;
  m[kBrushedDielectric].name = "brushed-dielectric";
  m[kBrushedDielectric].base_color = {0.08f, 0.22f, 0.6f, 1.0f};
  m[kBrushedDielectric].metallic = 0.0f;
  m[kBrushedDielectric].roughness = 0.35f;
  m[kBrushedDielectric].base_color_texture = {kBrushed, TextureTransform{{0.0f, 0.0f}, {4.0f, 1.0f}, 0.0f}};
  m[kBrushedDielectric].anisotropy = glm::vec2(0.7f, 0.5f);
  m[kBrushedDielectric].ior = 1.6f;
  m[kBrushedDielectric].specular = std::pair{0.8f, glm::vec3(1.0f, 0.9f, 0.8f)};
  m[kLanternGlow].name = "lantern-glow";
  m[kLanternGlow].base_color = {0.05f, 0.05f, 0.05f, 1.0f};
  m[kLanternGlow].metallic = 0.0f;
  m[kLanternGlow].roughness = 0.5f;
  m[kLanternGlow].emissive = {1.0f, 0.7f, 0.3f};
  m[kLanternGlow].emissive_texture = {kLantern, std::nullopt};
  m[kLanternGlow].emissive_strength = 6.0f;
  m[kRibbedPanel].name = "ribbed-panel";
  m[kRibbedPanel].base_color = {0.85f, 0.85f, 0.82f, 1.0f};
  m[kRibbedPanel].metallic = 0.0f;
  m[kRibbedPanel].roughness = 0.15f;
  m[kRibbedPanel].normal_texture = {kRibs, std::nullopt};
  m[kRibbedPanel].double_sided = true;
  return m;
}

std::vector<MeshDesc> showcase_meshes() {
  std::vector<MeshDesc> meshes;
  meshes.push_back({"ground", {primitive_from_mesh(make_plane({4.0f, 4.0f}, 1.0f, 8), false, kGround)}});
  meshes.push_back({"sphere", {primitive_from_mesh(make_sphere(0.6f, 48, 24), true, kDimpledGold)}});
  // No TANGENT: the importer must build the anisotropy frame itself (from the uv, like a normal map's).
  meshes.push_back({"torus", {primitive_from_mesh(make_torus(0.45f, 0.15f, 48, 16), false, kBrushedDielectric)}});
  // Two primitives, two materials; the caps reuse the sphere's normal-mapped material without TANGENT.
  meshes.push_back({"lantern",
                    {primitive_from_mesh(make_cube_faces(0.3f, true), false, kLanternGlow),
                     primitive_from_mesh(make_cube_faces(0.3f, false), false, kDimpledGold)}});
  meshes.push_back({"panel", {primitive_from_mesh(make_plane({1.2f, 0.8f}, 1.0f, 1), false, kRibbedPanel)}});
  return meshes;
}

std::vector<LightDesc> showcase_lights() {
  LightDesc sun{"sun", "directional", {1.0f, 0.96f, 0.9f}, 3.0f, std::nullopt};
  LightDesc bulb{"bulb", "point", {1.0f, 0.8f, 0.6f}, 5.0f, std::nullopt};  // no range: glintlab ignores it (a warning)
  LightDesc spot{"spot", "spot", {0.6f, 0.8f, 1.0f}, 15.0f, std::nullopt, 0.3f, 0.5f};
  return {sun, bulb, spot};
}

}  // namespace

Image8 make_image(int width, int height, const std::function<glm::vec4(glm::vec2 uv)>& rgba) {
  Image8 image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const glm::vec4 c = rgba({(static_cast<float>(i) + 0.5f) / static_cast<float>(width),
                                (static_cast<float>(j) + 0.5f) / static_cast<float>(height)});
      auto* texel = &image.rgba[(static_cast<std::size_t>(j) * width + i) * 4];
      for (int k = 0; k < 4; ++k) texel[k] = unorm8(c[k]);
    }
  return image;
}

Image8 make_normal_image(int width, int height, const std::function<glm::vec3(glm::vec2 uv)>& normal) {
  return make_image(width, height, [&](glm::vec2 uv) { return glm::vec4(glm::normalize(normal(uv)) * 0.5f + 0.5f, 1.0f); });
}

PrimitiveDesc primitive_from_mesh(const Mesh& mesh, bool with_tangents, int material) {
  PrimitiveDesc p;
  p.positions = mesh.positions;
  p.normals = mesh.normals;
  if (with_tangents) p.tangents = mesh.tangents;
  p.uvs.reserve(mesh.uvs.size());
  for (const glm::vec2& uv : mesh.uvs) p.uvs.emplace_back(uv.x, 1.0f - uv.y);
  p.indices = mesh.indices;
  p.material = material;
  return p;
}

Document make_showcase_document() {
  Document doc;
  doc.images = {checker_image(), roughness_metal_image(), dimple_normal_image(), rib_normal_image(),
                lantern_emissive_image(), brushed_image()};
  doc.materials = showcase_materials();
  doc.meshes = showcase_meshes();
  doc.lights = showcase_lights();
  doc.cameras.push_back({"view", true, 0.7f, 1.5f, 0.05f, 50.0f});

  const glm::vec3 eye(0.3f, 1.7f, 4.2f), sphere_at(-0.8f, 0.6f, 0.0f), lamps_at(0.0f, 0.5f, 0.0f);
  doc.nodes.reserve(12);  // node() hands out references into the vector
  auto node = [&](std::string name) -> NodeDesc& {
    doc.nodes.emplace_back().name = std::move(name);
    return doc.nodes.back();
  };
  // 0 showcase -> {1 ground, 2 objects -> {3 sphere, 4 torus -> 5 lantern, 6 panel}}
  node("showcase").rotation = glm::angleAxis(0.2f, glm::vec3(0, 1, 0));
  doc.nodes[0].children = {1, 2};
  node("ground").mesh = 0;
  NodeDesc& objects = node("objects");
  objects.translation = {0.1f, 0.0f, 0.0f};
  objects.scale = glm::vec3(1.1f);
  objects.children = {3, 4, 6};
  NodeDesc& sphere = node("dimpled-sphere");
  sphere.mesh = 1;
  sphere.translation = sphere_at;
  NodeDesc& torus = node("torus");
  torus.mesh = 2;
  torus.translation = {0.8f, 0.7f, -0.1f};
  torus.rotation = glm::angleAxis(1.1f, glm::vec3(1, 0, 0));
  torus.children = {5};
  NodeDesc& lantern = node("lantern");  // sits in the torus's hole
  lantern.mesh = 3;
  lantern.rotation = glm::angleAxis(glm::quarter_pi<float>(), glm::vec3(0, 1, 0));
  lantern.scale = {0.8f, 0.7f, 0.8f};
  NodeDesc& panel = node("ribbed-panel");
  panel.mesh = 4;
  panel.translation = {0.0f, 0.75f, -1.2f};
  panel.rotation = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));  // +y -> +z: faces the camera
  // 7 sun; 8 lamps -> {9 bulb, 10 spot}; 11 camera
  NodeDesc& sun = node("sun");
  sun.light = 0;
  sun.rotation = look_at(glm::vec3(0), glm::vec3(-0.5f, -1.0f, -0.3f));
  NodeDesc& lamps = node("lamps");
  lamps.translation = lamps_at;
  lamps.children = {9, 10};
  NodeDesc& bulb = node("bulb");
  bulb.light = 1;
  bulb.translation = {1.5f, 1.3f, 1.2f};
  NodeDesc& spot = node("spot");
  spot.light = 2;
  spot.translation = {-1.6f, 1.7f, 1.0f};
  spot.rotation = look_at(lamps_at + spot.translation, sphere_at);
  NodeDesc& camera = node("camera");
  camera.camera = 0;
  camera.translation = eye;
  camera.rotation = look_at(eye, {0.0f, 0.5f, -0.1f});
  doc.scene_nodes = {0, 7, 8, 11};
  return doc;
}

}  // namespace glintlab::gltf
