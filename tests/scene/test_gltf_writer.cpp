// glintlab's glTF writer (scene/gltf/gltf_writer.hpp), read back with TinyGLTF's loader: a textured quad
// round-trips exactly through .glb and .gltf, the binary layout follows the glTF 2.0 spec
// (chunks, 4-byte alignment, strides, targets, POSITION bounds), and inconsistent documents are
// rejected before anything is written.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <iterator>
#include <map>

#include "core/error.hpp"
#include "scene/gltf_test_support.hpp"
#include "scene/gltf/gltf_writer.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
using namespace glintlab::gltf;
using namespace glintlab::test;

namespace {

/// A 2x3 image whose every byte differs, so a flipped, transposed or shifted decode shows.
Image8 distinct_image() {
  Image8 image{2, 3, {}};
  for (int k = 0; k < 2 * 3 * 4; ++k) image.rgba.push_back(static_cast<std::uint8_t>(10 * k + 3));
  return image;
}

Document textured_quad() {
  Document doc;
  doc.images.push_back(distinct_image());
  MaterialDesc m;
  m.name = "quad-material";
  m.base_color = {0.9f, 0.5f, 0.25f, 1.0f};
  m.base_color_texture = {0, TextureTransform{{0.125f, -0.5f}, {2.0f, 3.0f}, 0.3f}};
  m.metallic = 0.3f;
  m.roughness = 0.7f;
  doc.materials.push_back(m);
  PrimitiveDesc p;
  p.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0.5f, 1}, {-1, 0, 1}};
  p.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  p.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}};
  p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0.25f, 0.75f}};
  p.indices = {0, 3, 2, 0, 2, 1};
  p.material = 0;
  doc.meshes.push_back({"quad", {p}});
  NodeDesc node;
  node.name = "quad-node";
  node.mesh = 0;
  node.translation = {0.5f, -2.0f, 3.0f};
  node.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  node.scale = {1.0f, 2.0f, 0.5f};
  doc.nodes.push_back(node);
  doc.scene_nodes = {0};
  return doc;
}

void expect_quad_round_trips(const tinygltf::Model& model, const Document& doc) {
  const PrimitiveDesc& p = doc.meshes[0].primitives[0];
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  const auto& prim = model.meshes[0].primitives[0];
  EXPECT_EQ(prim.mode, TINYGLTF_MODE_TRIANGLES);
  EXPECT_EQ(prim.material, 0);
  EXPECT_EQ(read_accessor<glm::vec3>(model, prim.attributes.at("POSITION")), p.positions);
  EXPECT_EQ(read_accessor<glm::vec3>(model, prim.attributes.at("NORMAL")), p.normals);
  EXPECT_EQ(read_accessor<glm::vec4>(model, prim.attributes.at("TANGENT")), p.tangents);
  EXPECT_EQ(read_accessor<glm::vec2>(model, prim.attributes.at("TEXCOORD_0")), p.uvs);
  EXPECT_EQ(read_indices(model, prim.indices), p.indices);

  ASSERT_EQ(model.materials.size(), 1u);
  const auto& m = model.materials[0];
  EXPECT_EQ(m.name, "quad-material");
  const auto& pbr = m.pbrMetallicRoughness;
  EXPECT_EQ(pbr.baseColorFactor, (std::vector<double>{0.9f, 0.5f, 0.25f, 1.0f}));
  EXPECT_EQ(static_cast<float>(pbr.metallicFactor), 0.3f);
  EXPECT_EQ(static_cast<float>(pbr.roughnessFactor), 0.7f);
  ASSERT_EQ(pbr.baseColorTexture.index, 0);
  EXPECT_EQ(pbr.metallicRoughnessTexture.index, -1);
  const auto& transform = pbr.baseColorTexture.extensions.at("KHR_texture_transform");
  EXPECT_EQ(static_cast<float>(transform.Get("offset").Get(0).GetNumberAsDouble()), 0.125f);
  EXPECT_EQ(static_cast<float>(transform.Get("offset").Get(1).GetNumberAsDouble()), -0.5f);
  EXPECT_EQ(static_cast<float>(transform.Get("scale").Get(0).GetNumberAsDouble()), 2.0f);
  EXPECT_EQ(static_cast<float>(transform.Get("scale").Get(1).GetNumberAsDouble()), 3.0f);
  EXPECT_EQ(number(transform, "rotation"), 0.3f);
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"KHR_texture_transform"});
  EXPECT_TRUE(model.extensionsRequired.empty());

  ASSERT_EQ(model.textures.size(), 1u);
  EXPECT_EQ(model.textures[0].source, 0);
  ASSERT_EQ(model.samplers.size(), 1u);
  EXPECT_EQ(model.samplers[0].minFilter, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(model.samplers[0].magFilter, TINYGLTF_TEXTURE_FILTER_LINEAR);
  EXPECT_EQ(model.samplers[0].wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
  EXPECT_EQ(model.samplers[0].wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
  ASSERT_EQ(model.images.size(), 1u);
  const auto& image = model.images[0];
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_GE(image.bufferView, 0);
  EXPECT_EQ(image.width, 2);
  EXPECT_EQ(image.height, 3);
  EXPECT_EQ(image.component, 4);
  EXPECT_EQ(image.bits, 8);
  EXPECT_EQ(image.image, doc.images[0].rgba);

  ASSERT_EQ(model.nodes.size(), 1u);
  const auto& node = model.nodes[0];
  const NodeDesc& want = doc.nodes[0];
  EXPECT_EQ(node.mesh, 0);
  EXPECT_EQ(node.translation, (std::vector<double>{0.5f, -2.0f, 3.0f}));
  EXPECT_EQ(node.rotation, (std::vector<double>{want.rotation.x, want.rotation.y, want.rotation.z, want.rotation.w}));
  EXPECT_EQ(node.scale, (std::vector<double>{1.0f, 2.0f, 0.5f}));
  EXPECT_TRUE(node.matrix.empty());
  ASSERT_EQ(model.scenes.size(), 1u);
  EXPECT_EQ(model.defaultScene, 0);
  EXPECT_EQ(model.scenes[0].nodes, std::vector<int>{0});
  EXPECT_EQ(model.asset.version, "2.0");
}

std::uint32_t u32_at(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

std::string write_error(const Document& doc) {
  try {
    encode_glb(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GltfWriter, TexturedQuadRoundTripsExactlyThroughGlb) {
  const Document doc = textured_quad();
  expect_quad_round_trips(load_glb(encode_glb(doc)), doc);
}

TEST(GltfWriter, TexturedQuadRoundTripsExactlyThroughGltfWithDataUris) {
  const Document doc = textured_quad();
  ScratchDirectory dir;
  write_gltf(dir / "quad.gltf", doc);
  expect_quad_round_trips(load_gltf_file(dir / "quad.gltf"), doc);
  // Self-contained: one file, its buffer a data URI, nothing else written (no .bin, no temporary).
  const auto entries = std::distance(std::filesystem::directory_iterator(dir.path()), {});
  EXPECT_EQ(entries, 1);
  std::ifstream in(dir / "quad.gltf");
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  EXPECT_NE(text.find("\"uri\": \"data:application/octet-stream;base64,"), std::string::npos);
}

TEST(GltfWriter, GlbChunksAreAlignedAndSized) {
  const auto bytes = encode_glb(textured_quad());
  ASSERT_GE(bytes.size(), 28u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");
  EXPECT_EQ(u32_at(bytes, 4), 2u);
  EXPECT_EQ(u32_at(bytes, 8), bytes.size());
  const std::uint32_t json_length = u32_at(bytes, 12);
  EXPECT_EQ(u32_at(bytes, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_EQ(json_length % 4, 0u);
  const std::size_t bin_at = 20 + json_length;
  ASSERT_LE(bin_at + 8, bytes.size());
  const std::uint32_t bin_length = u32_at(bytes, bin_at);
  EXPECT_EQ(u32_at(bytes, bin_at + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(bin_length % 4, 0u);
  EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
  const auto model = load_glb(bytes);
  ASSERT_EQ(model.buffers.size(), 1u);
  EXPECT_TRUE(model.buffers[0].uri.empty());
  EXPECT_EQ(model.buffers[0].data.size(), bin_length);  // byteLength padded to 4 by the writer
}

TEST(GltfWriter, ViewsAreAlignedStridedAndTargeted) {
  const auto model = load_glb(encode_glb(textured_quad()));
  const auto& prim = model.meshes[0].primitives[0];
  const std::map<std::string, std::size_t> element_size{
      {"POSITION", 12}, {"NORMAL", 12}, {"TANGENT", 16}, {"TEXCOORD_0", 8}};
  for (const auto& [name, accessor_index] : prim.attributes) {
    const auto& accessor = model.accessors[static_cast<std::size_t>(accessor_index)];
    const auto& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT) << name;
    EXPECT_EQ(view.byteStride, element_size.at(name)) << name;
    EXPECT_EQ(view.target, TINYGLTF_TARGET_ARRAY_BUFFER) << name;
    EXPECT_EQ(view.byteOffset % 4, 0u) << name;
    EXPECT_EQ(view.byteLength, accessor.count * element_size.at(name)) << name;
  }
  const auto& indices = model.accessors[static_cast<std::size_t>(prim.indices)];
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  const auto& index_view = model.bufferViews[static_cast<std::size_t>(indices.bufferView)];
  EXPECT_EQ(index_view.byteStride, 0u);  // 3.6.2.4: index views must not have a stride
  EXPECT_EQ(index_view.target, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  EXPECT_EQ(index_view.byteLength, 12u);
  // The PNG's view comes first; its length need not be a multiple of 4, the views after it start
  // on a 4-byte boundary all the same (checked above).
  const auto& image_view = model.bufferViews[static_cast<std::size_t>(model.images[0].bufferView)];
  EXPECT_EQ(image_view.byteOffset % 4, 0u);
  EXPECT_EQ(image_view.target, 0);
  EXPECT_EQ(image_view.byteStride, 0u);
  // POSITION's bounds are required (3.7.2.1) and exact.
  const auto& position = model.accessors[static_cast<std::size_t>(prim.attributes.at("POSITION"))];
  EXPECT_EQ(position.minValues, (std::vector<double>{-1, 0, -1}));
  EXPECT_EQ(position.maxValues, (std::vector<double>{1, 0.5, 1}));
}

TEST(GltfWriter, IndicesWidenToUnsignedIntOnlyWhenAShortCannotHoldThem) {
  for (const std::size_t vertices : {std::size_t{65535}, std::size_t{65536}}) {
    Document doc;
    PrimitiveDesc p;
    p.positions.resize(vertices, glm::vec3(0));
    p.positions[1] = {1, 0, 0};
    p.positions.back() = {0, 1, 0};
    p.indices = {0, 1, static_cast<std::uint32_t>(vertices - 1)};
    doc.meshes.push_back({"big", {p}});
    const auto model = load_glb(encode_glb(doc));
    const int accessor = model.meshes[0].primitives[0].indices;
    // 65535 is the unsigned short primitive-restart value, which glTF forbids as an index.
    EXPECT_EQ(model.accessors[static_cast<std::size_t>(accessor)].componentType,
              vertices <= 65535 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    EXPECT_EQ(read_indices(model, accessor), p.indices);
  }
}

TEST(GltfWriter, NodeMatrixReplacesTranslationRotationScale) {
  Document doc = textured_quad();
  glm::mat4 m(1.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = static_cast<float>(c * 4 + r) * 0.125f;
  doc.nodes[0].matrix = m;
  const auto model = load_glb(encode_glb(doc));
  const auto& node = model.nodes[0];
  EXPECT_TRUE(node.translation.empty() && node.rotation.empty() && node.scale.empty());
  ASSERT_EQ(node.matrix.size(), 16u);
  for (int c = 0; c < 4; ++c)  // glTF's matrix is column-major, like glm
    for (int r = 0; r < 4; ++r) EXPECT_EQ(node.matrix[static_cast<std::size_t>(c * 4 + r)], m[c][r]);
}

TEST(GltfWriter, ExtraExtensionsAreListedAndWrittenAsEmptyObjects) {
  Document doc = textured_quad();
  doc.materials[0].extra_extensions = {"KHR_materials_clearcoat"};
  doc.extra_extensions_used = {"EXT_glintlab_unknown"};
  const auto model = load_glb(encode_glb(doc));
  EXPECT_EQ(model.extensionsUsed,
            (std::vector<std::string>{"KHR_texture_transform", "KHR_materials_clearcoat", "EXT_glintlab_unknown"}));
  ASSERT_TRUE(model.materials[0].extensions.count("KHR_materials_clearcoat"));
  EXPECT_TRUE(model.materials[0].extensions.at("KHR_materials_clearcoat").IsObject());
}

TEST(GltfWriter, InconsistentDocumentsAreRejectedNamingTheElement) {
  const Document good = textured_quad();
  auto error_with = [&](auto&& change) {
    Document doc = good;
    change(doc);
    return write_error(doc);
  };
  EXPECT_EQ(write_error(good), "");
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].indices[4] = 4; })
                .find("mesh 0 primitive 0: index 4 out of range (4 vertices)"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].indices.pop_back(); }).find("multiple of 3"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].uvs.pop_back(); }).find("uv count"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].tangents[1].w = 0.0f; }).find("tangent 1"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].positions[2].y = NAN; }).find("position 2"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.images[0].rgba.pop_back(); }).find("image 0"), std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.materials[0].normal_texture.image = 1; }).find("material 0: image 1"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.materials[0].roughness = 1.5f; }).find("roughnessFactor"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.meshes[0].primitives[0].material = 3; }).find("material 3"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.nodes[0].rotation = glm::quat(2, 0, 0, 0); }).find("unit quaternion"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.nodes[0].children = {0}; }).find("cycle"), std::string::npos);
  EXPECT_NE(error_with([](Document& d) {
              d.nodes.resize(3);
              d.nodes[1].children = {0};
              d.nodes[2].children = {0};
            }).find("already has parent"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) {
              d.nodes.resize(2);
              d.nodes[1].children = {0};
            }).find("scene: node 0 is not a root"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.lights.push_back({"l", "area"}); }).find("light 0: type 'area'"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) {
              d.lights.push_back({"s", "spot", glm::vec3(1), 1.0f, std::nullopt, 0.6f, 0.5f});
            }).find("light 0"),
            std::string::npos);
  EXPECT_NE(error_with([](Document& d) { d.cameras.push_back({"c", true, 0.8f, 0.0f, 1.0f, 0.5f}); }).find("zfar"),
            std::string::npos);
}

TEST(GltfWriter, WritesByExtensionInAnyCaseAndNothingOnFailure) {
  ScratchDirectory dir;
  write_gltf(dir / "a.GLB", textured_quad());
  std::ifstream in(dir / "a.GLB", std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(bytes, encode_glb(textured_quad()));  // deterministic, and the file is the binary form
  EXPECT_THROW(write_gltf(dir / "b.obj", textured_quad()), InputError);
  Document bad = textured_quad();
  bad.meshes[0].primitives[0].indices[0] = 99;
  EXPECT_THROW(write_gltf(dir / "c.glb", bad), InputError);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}
