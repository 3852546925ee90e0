// The showcase model (scene/gltf/gltf_showcase.hpp) that the built-in glTF scene loads, read back with
// TinyGLTF's loader: everything the importer must handle is present and correct (materials and
// their extensions, texture transforms, lights, camera, a nested hierarchy, primitives with and
// without TANGENT), the PNGs decode to the document's pixels, and tangents and normal maps follow
// glTF's conventions (bitangent up in the image, green = up).
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <set>

#include "scene/gltf/gltf_showcase.hpp"
#include "scene/gltf_test_support.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
using namespace glintlab::gltf;
using namespace glintlab::test;

namespace {

const Document& showcase() {
  static const Document doc = make_showcase_document();
  return doc;
}

const tinygltf::Model& showcase_glb() {
  static const tinygltf::Model model = load_glb(encode_glb(showcase()));
  return model;
}

std::vector<float> floats(const std::vector<double>& values) { return {values.begin(), values.end()}; }

/// glTF 3.5.3: local = T * R * S, or the matrix.
glm::mat4 local_matrix(const tinygltf::Node& n) {
  if (!n.matrix.empty()) return glm::make_mat4(floats(n.matrix).data());
  glm::mat4 m(1.0f);
  if (!n.translation.empty()) m[3] = glm::vec4(glm::make_vec3(floats(n.translation).data()), 1.0f);
  if (!n.rotation.empty()) {
    const auto r = floats(n.rotation);
    m = m * glm::mat4_cast(glm::quat(r[3], r[0], r[1], r[2]));
  }
  if (!n.scale.empty()) m = glm::scale(m, glm::make_vec3(floats(n.scale).data()));
  return m;
}

void collect_world(const tinygltf::Model& model, int node, const glm::mat4& parent, std::vector<glm::mat4>& world,
                   std::vector<int>& depth, int level) {
  const auto i = static_cast<std::size_t>(node);
  world[i] = parent * local_matrix(model.nodes[i]);
  depth[i] = level;
  for (int child : model.nodes[i].children) collect_world(model, child, world[i], world, depth, level + 1);
}

void expect_texture(const tinygltf::TextureInfo& info, const TextureRef& want, const std::string& what) {
  ASSERT_EQ(info.index, want.image) << what;
  ASSERT_EQ(info.extensions.count("KHR_texture_transform"), want.transform ? 1u : 0u) << what;
  if (!want.transform) return;
  const auto& t = info.extensions.at("KHR_texture_transform");
  EXPECT_EQ(number(t, "rotation"), want.transform->rotation) << what;
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(static_cast<float>(t.Get("offset").Get(k).GetNumberAsDouble()), want.transform->offset[k]) << what;
    EXPECT_EQ(static_cast<float>(t.Get("scale").Get(k).GetNumberAsDouble()), want.transform->scale[k]) << what;
  }
}

}  // namespace

TEST(GltfShowcase, IsASmallDeterministicModelWithEverythingTheImporterHandles) {
  const Document& doc = showcase();
  EXPECT_GE(doc.materials.size(), 4u);
  EXPECT_GE(doc.meshes.size(), 4u);
  std::size_t triangles = 0, with_tangents = 0, without_tangents = 0;
  for (const auto& mesh : doc.meshes)
    for (const auto& p : mesh.primitives) {
      triangles += p.indices.size() / 3;
      (p.tangents.empty() ? without_tangents : with_tangents)++;
    }
  EXPECT_GE(triangles, 2000u);
  EXPECT_LE(triangles, 10000u);
  EXPECT_GE(with_tangents, 1u);
  EXPECT_GE(without_tangents, 1u);
  for (const auto& image : doc.images) EXPECT_LE(std::max(image.width, image.height), 256);
  EXPECT_EQ(encode_glb(doc), encode_glb(make_showcase_document()));
}

TEST(GltfShowcase, GlbAndGltfHoldTheSameDataAsTheDocument) {
  ScratchDirectory dir;
  write_gltf(dir / "showcase.gltf", showcase());
  const tinygltf::Model text = load_gltf_file(dir / "showcase.gltf");
  const tinygltf::Model& binary = showcase_glb();
  for (const tinygltf::Model* model : {&binary, &text}) {
    EXPECT_EQ(model->images.size(), 6u);
    EXPECT_EQ(model->textures.size(), 6u);
    EXPECT_EQ(model->samplers.size(), 1u);
    EXPECT_EQ(model->materials.size(), 5u);
    EXPECT_EQ(model->meshes.size(), 5u);
    EXPECT_EQ(model->lights.size(), 3u);
    EXPECT_EQ(model->cameras.size(), 1u);
    EXPECT_EQ(model->nodes.size(), 12u);
    ASSERT_EQ(model->buffers.size(), 1u);
    for (std::size_t m = 0; m < showcase().meshes.size(); ++m) {
      const auto& want = showcase().meshes[m];
      const auto& got = model->meshes[m];
      EXPECT_EQ(got.name, want.name);
      ASSERT_EQ(got.primitives.size(), want.primitives.size());
      for (std::size_t k = 0; k < want.primitives.size(); ++k) {
        const auto& p = want.primitives[k];
        const auto& attributes = got.primitives[k].attributes;
        EXPECT_EQ(read_accessor<glm::vec3>(*model, attributes.at("POSITION")), p.positions);
        EXPECT_EQ(read_accessor<glm::vec3>(*model, attributes.at("NORMAL")), p.normals);
        EXPECT_EQ(read_accessor<glm::vec2>(*model, attributes.at("TEXCOORD_0")), p.uvs);
        EXPECT_EQ(attributes.count("TANGENT"), p.tangents.empty() ? 0u : 1u);
        if (!p.tangents.empty()) {
          EXPECT_EQ(read_accessor<glm::vec4>(*model, attributes.at("TANGENT")), p.tangents);
        }
        EXPECT_EQ(read_indices(*model, got.primitives[k].indices), p.indices);
        EXPECT_EQ(got.primitives[k].material, p.material);
        // POSITION bounds are required and must be the data's own.
        const auto& accessor = model->accessors[static_cast<std::size_t>(attributes.at("POSITION"))];
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const auto& v : p.positions) lo = glm::min(lo, v), hi = glm::max(hi, v);
        EXPECT_EQ(accessor.minValues, (std::vector<double>{lo.x, lo.y, lo.z}));
        EXPECT_EQ(accessor.maxValues, (std::vector<double>{hi.x, hi.y, hi.z}));
      }
    }
    for (const auto& view : model->bufferViews) {
      EXPECT_EQ(view.byteOffset % 4, 0u);
      EXPECT_LE(view.byteOffset + view.byteLength, model->buffers[0].data.size());
      const bool vertex_data = view.target == TINYGLTF_TARGET_ARRAY_BUFFER;
      EXPECT_EQ(view.byteStride % 4, 0u);
      EXPECT_EQ(view.byteStride != 0, vertex_data);  // strides on vertex views only
    }
  }
  EXPECT_EQ(text.buffers[0].data, binary.buffers[0].data);
}

TEST(GltfShowcase, MaterialsFactorsTexturesAndExtensionsAreWritten) {
  const tinygltf::Model& model = showcase_glb();
  const Document& doc = showcase();
  for (std::size_t i = 0; i < doc.materials.size(); ++i) {
    const MaterialDesc& want = doc.materials[i];
    const tinygltf::Material& got = model.materials[i];
    const auto& pbr = got.pbrMetallicRoughness;
    EXPECT_EQ(got.name, want.name);
    EXPECT_EQ(floats(pbr.baseColorFactor), (std::vector<float>{want.base_color.r, want.base_color.g,
                                                               want.base_color.b, want.base_color.a}));
    EXPECT_EQ(static_cast<float>(pbr.metallicFactor), want.metallic) << want.name;
    EXPECT_EQ(static_cast<float>(pbr.roughnessFactor), want.roughness) << want.name;
    EXPECT_EQ(floats(got.emissiveFactor), (std::vector<float>{want.emissive.r, want.emissive.g, want.emissive.b}));
    EXPECT_EQ(got.doubleSided, want.double_sided);
    expect_texture(pbr.baseColorTexture, want.base_color_texture, want.name + " baseColor");
    expect_texture(pbr.metallicRoughnessTexture, want.metallic_roughness_texture, want.name + " metallicRoughness");
    expect_texture(got.emissiveTexture, want.emissive_texture, want.name + " emissive");
    ASSERT_EQ(got.normalTexture.index, want.normal_texture.image);
    if (want.normal_texture.image >= 0) {
      EXPECT_EQ(static_cast<float>(got.normalTexture.scale), want.normal_scale);
    }
    const auto& ext = got.extensions;
    ASSERT_EQ(ext.count("KHR_materials_emissive_strength"), want.emissive_strength ? 1u : 0u);
    if (want.emissive_strength) {
      EXPECT_EQ(number(ext.at("KHR_materials_emissive_strength"), "emissiveStrength"), *want.emissive_strength);
    }
    ASSERT_EQ(ext.count("KHR_materials_anisotropy"), want.anisotropy ? 1u : 0u);
    if (want.anisotropy) {
      EXPECT_EQ(number(ext.at("KHR_materials_anisotropy"), "anisotropyStrength"), want.anisotropy->x);
      EXPECT_EQ(number(ext.at("KHR_materials_anisotropy"), "anisotropyRotation"), want.anisotropy->y);
    }
    ASSERT_EQ(ext.count("KHR_materials_ior"), want.ior ? 1u : 0u);
    if (want.ior) {
      EXPECT_EQ(number(ext.at("KHR_materials_ior"), "ior"), *want.ior);
    }
    ASSERT_EQ(ext.count("KHR_materials_specular"), want.specular ? 1u : 0u);
    if (want.specular) {
      const auto& s = ext.at("KHR_materials_specular");
      EXPECT_EQ(number(s, "specularFactor"), want.specular->first);
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(static_cast<float>(s.Get("specularColorFactor").Get(c).GetNumberAsDouble()), want.specular->second[c]);
    }
  }
  // Every extension the showcase uses, listed once; none required (all have core fallbacks).
  const std::set<std::string> used(model.extensionsUsed.begin(), model.extensionsUsed.end());
  EXPECT_EQ(used.size(), model.extensionsUsed.size());
  EXPECT_EQ(used, (std::set<std::string>{"KHR_texture_transform", "KHR_materials_emissive_strength",
                                         "KHR_materials_anisotropy", "KHR_materials_ior", "KHR_materials_specular",
                                         "KHR_lights_punctual"}));
  EXPECT_TRUE(model.extensionsRequired.empty());
  // The ground's two textures carry different, non-trivial transforms.
  const auto& ground = doc.materials[0];
  ASSERT_TRUE(ground.base_color_texture.transform && ground.metallic_roughness_texture.transform);
  EXPECT_NE(ground.base_color_texture.transform->rotation, ground.metallic_roughness_texture.transform->rotation);
  EXPECT_NE(ground.base_color_texture.transform->offset, glm::vec2(0));
  EXPECT_NE(ground.base_color_texture.transform->scale, glm::vec2(1));
}

TEST(GltfShowcase, LightsCameraAndNestedNodesAreWritten) {
  const tinygltf::Model& model = showcase_glb();
  const Document& doc = showcase();
  std::set<std::string> types;
  for (std::size_t i = 0; i < doc.lights.size(); ++i) {
    const auto& got = model.lights[i];
    const auto& want = doc.lights[i];
    types.insert(got.type);
    EXPECT_EQ(got.type, want.type);
    EXPECT_EQ(floats(got.color), (std::vector<float>{want.colour.r, want.colour.g, want.colour.b}));
    EXPECT_EQ(static_cast<float>(got.intensity), want.intensity);
    EXPECT_EQ(static_cast<float>(got.range), want.range.value_or(0.0f));  // 0: absent = infinite
    if (want.type == "spot") {
      EXPECT_EQ(static_cast<float>(got.spot.innerConeAngle), want.inner_cone);
      EXPECT_EQ(static_cast<float>(got.spot.outerConeAngle), want.outer_cone);
    }
  }
  EXPECT_EQ(types, (std::set<std::string>{"directional", "point", "spot"}));
  ASSERT_EQ(model.cameras.size(), 1u);
  const auto& camera = model.cameras[0];
  EXPECT_EQ(camera.type, "perspective");
  EXPECT_EQ(static_cast<float>(camera.perspective.yfov), doc.cameras[0].yfov);
  EXPECT_EQ(static_cast<float>(camera.perspective.aspectRatio), doc.cameras[0].aspect);
  EXPECT_EQ(static_cast<float>(camera.perspective.znear), doc.cameras[0].znear);
  EXPECT_EQ(static_cast<float>(camera.perspective.zfar), doc.cameras[0].zfar);

  std::vector<int> light_users(doc.lights.size(), 0);
  for (std::size_t i = 0; i < doc.nodes.size(); ++i) {
    const auto& got = model.nodes[i];
    const auto& want = doc.nodes[i];
    EXPECT_EQ(got.name, want.name);
    EXPECT_EQ(got.mesh, want.mesh);
    EXPECT_EQ(got.camera, want.camera);
    EXPECT_EQ(got.children, want.children);
    const glm::mat4 expected = glm::translate(glm::mat4(1.0f), want.translation) * glm::mat4_cast(want.rotation) *
                               glm::scale(glm::mat4(1.0f), want.scale);
    const glm::mat4 written = local_matrix(got);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(written[c][r], expected[c][r], 1e-6f) << want.name;
    ASSERT_EQ(got.extensions.count("KHR_lights_punctual"), want.light >= 0 ? 1u : 0u) << want.name;
    if (want.light >= 0) {
      const int light = got.extensions.at("KHR_lights_punctual").Get("light").GetNumberAsInt();
      EXPECT_EQ(light, want.light);
      light_users[static_cast<std::size_t>(light)]++;
    }
  }
  EXPECT_EQ(light_users, std::vector<int>(doc.lights.size(), 1));
  EXPECT_EQ(model.scenes[0].nodes, doc.scene_nodes);
}

TEST(GltfShowcase, ObjectsLieNearTheOriginInFrontOfTheCamera) {
  const tinygltf::Model& model = showcase_glb();
  std::vector<glm::mat4> world(model.nodes.size(), glm::mat4(1.0f));
  std::vector<int> depth(model.nodes.size(), -1);
  for (int root : model.scenes[0].nodes) collect_world(model, root, glm::mat4(1.0f), world, depth, 0);
  EXPECT_GE(*std::max_element(depth.begin(), depth.end()), 3);  // showcase -> objects -> torus -> lantern
  EXPECT_EQ(std::count(depth.begin(), depth.end(), -1), 0);     // every node is in the scene
  const auto camera_node = static_cast<std::size_t>(
      std::find_if(model.nodes.begin(), model.nodes.end(), [](const auto& n) { return n.camera == 0; }) -
      model.nodes.begin());
  const glm::mat4 view = glm::inverse(world[camera_node]);
  const float tan_half_y = std::tan(0.5f * static_cast<float>(model.cameras[0].perspective.yfov));
  const float tan_half_x = tan_half_y * static_cast<float>(model.cameras[0].perspective.aspectRatio);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    if (model.nodes[i].mesh < 0) continue;
    for (const auto& prim : model.meshes[static_cast<std::size_t>(model.nodes[i].mesh)].primitives) {
      const auto& a = model.accessors[static_cast<std::size_t>(prim.attributes.at("POSITION"))];
      for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p;
        for (int k = 0; k < 3; ++k)
          p[k] = static_cast<float>(((corner >> k) & 1) ? a.maxValues[static_cast<std::size_t>(k)]
                                                        : a.minValues[static_cast<std::size_t>(k)]);
        const glm::vec3 w(world[i] * glm::vec4(p, 1.0f));
        EXPECT_LE(glm::length(glm::vec2(w.x, w.z)), 2.9f) << model.nodes[i].name;  // the 4x4 ground's corners
        EXPECT_GE(w.y, -1e-4f) << model.nodes[i].name;
        EXPECT_LE(w.y, 2.0f) << model.nodes[i].name;
        if (model.nodes[i].name == "ground") continue;  // the ground may reach past the frame
        const glm::vec3 c(view * glm::vec4(w, 1.0f));
        EXPECT_LT(c.z, 0.0f) << model.nodes[i].name;  // the camera looks along -z
        EXPECT_LE(std::abs(c.x / c.z), tan_half_x) << model.nodes[i].name;
        EXPECT_LE(std::abs(c.y / c.z), tan_half_y) << model.nodes[i].name;
      }
    }
  }
}

TEST(GltfShowcase, EmbeddedPngsDecodeToTheDocumentsPixels) {
  const tinygltf::Model& model = showcase_glb();
  ASSERT_EQ(model.images.size(), showcase().images.size());
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    const auto& got = model.images[i];
    const auto& want = showcase().images[i];
    EXPECT_EQ(got.mimeType, "image/png");
    EXPECT_EQ(got.width, want.width);
    EXPECT_EQ(got.height, want.height);
    EXPECT_EQ(got.component, 4);
    EXPECT_EQ(got.bits, 8);
    EXPECT_TRUE(got.image == want.rgba) << "image " << i;
    EXPECT_EQ(model.textures[i].source, static_cast<int>(i));
  }
}

// glTF 3.7.2.1: bitangent = cross(normal, tangent.xyz) * w, with +Y of the normal map up in the
// image, i.e. along -dP/dv. Checked against the uv gradients of the written triangles (not the
// writer's code): tangent.xyz along +dP/du, bitangent against +dP/dv, w = +-1, xyz unit.
TEST(GltfShowcase, TangentsPointAlongUAndBitangentsUpTheImage) {
  const tinygltf::Model& model = showcase_glb();
  int checked = 0;
  for (const auto& mesh : model.meshes)
    for (const auto& prim : mesh.primitives) {
      if (!prim.attributes.count("TANGENT")) continue;
      const auto positions = read_accessor<glm::vec3>(model, prim.attributes.at("POSITION"));
      const auto normals = read_accessor<glm::vec3>(model, prim.attributes.at("NORMAL"));
      const auto tangents = read_accessor<glm::vec4>(model, prim.attributes.at("TANGENT"));
      const auto uvs = read_accessor<glm::vec2>(model, prim.attributes.at("TEXCOORD_0"));
      const auto indices = read_indices(model, prim.indices);
      std::vector<glm::vec3> dp_du(positions.size(), glm::vec3(0)), dp_dv(positions.size(), glm::vec3(0));
      for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const auto i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        const glm::vec3 e1 = positions[i1] - positions[i0], e2 = positions[i2] - positions[i0];
        const glm::vec2 d1 = uvs[i1] - uvs[i0], d2 = uvs[i2] - uvs[i0];
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        for (auto i : {i0, i1, i2}) {
          dp_du[i] += (e1 * d2.y - e2 * d1.y) / det;
          dp_dv[i] += (e2 * d1.x - e1 * d2.x) / det;
        }
      }
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec4 t = tangents[i];
        EXPECT_EQ(std::abs(t.w), 1.0f);
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
        if (glm::length(dp_du[i]) < 1e-4f || glm::length(dp_dv[i]) < 1e-4f) continue;  // sphere poles
        const glm::vec3 bitangent = glm::cross(normals[i], glm::vec3(t)) * t.w;
        EXPECT_GT(glm::dot(glm::vec3(t), glm::normalize(dp_du[i])), 0.5f) << mesh.name << " vertex " << i;
        EXPECT_LT(glm::dot(bitangent, glm::normalize(dp_dv[i])), -0.5f) << mesh.name << " vertex " << i;
        ++checked;
      }
    }
  EXPECT_GT(checked, 1000);
}

// The dimple map (image 2): a dimple's wall above its centre in the image faces down towards the
// centre (green < 0.5), the wall to the right faces left (red < 0.5); flat texels are (0.5, 0.5, 1).
TEST(GltfShowcase, NormalMapsUseGltfsGreenUpConvention) {
  const Image8& dimples = showcase().images[2];
  auto texel = [&](float u, float v) {
    const int i = static_cast<int>(u * static_cast<float>(dimples.width));
    const int j = static_cast<int>(v * static_cast<float>(dimples.height));
    const auto* p = &dimples.rgba[(static_cast<std::size_t>(j) * static_cast<std::size_t>(dimples.width) +
                                   static_cast<std::size_t>(i)) * 4];
    return glm::ivec3(p[0], p[1], p[2]);
  };
  const float u = 5.5f / 16.0f, v = 2.5f / 8.0f;  // centre of an unstaggered dimple (rows 0, 2, 4...)
  const float du = 0.2f / 16.0f, dv = 0.2f / 8.0f;
  EXPECT_LT(texel(u, v - dv).g, 118);  // above
  EXPECT_GT(texel(u, v + dv).g, 138);  // below
  EXPECT_LT(texel(u + du, v).r, 118);  // right
  EXPECT_GT(texel(u - du, v).r, 138);  // left
  EXPECT_LT(std::abs(texel(u, v - dv).r - 128), std::abs(texel(u, v - dv).g - 128));  // tilted mostly in y
  EXPECT_EQ(texel(5.0f / 16.0f + 1e-3f, 2.0f / 8.0f + 1e-3f), glm::ivec3(128, 128, 255));  // a cell corner
}
