// glTF import (scene/gltf/gltf_import.hpp) and its place in scene files, on documents glintlab's own
// writer makes: materials and their extensions in glintlab's form, uv and texture rows flipped to
// v up, texture transforms conjugated by that flip, the file's tangents kept, lights and cameras
// in the world, unimplemented extensions named, and every failure an InputError naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "core/error.hpp"
#include "scene/gltf/gltf_import.hpp"
#include "scene/gltf/gltf_showcase.hpp"
#include "scene/gltf/gltf_writer.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/scene_loader.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
using namespace glintlab::gltf;
using namespace glintlab::test;

namespace {

GltfAsset showcase() { return import_glb(encode_glb(make_showcase_document()), "showcase.glb"); }

const Material& material_named(const GltfAsset& a, const std::string& name) {
  for (const auto& m : a.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

/// A unit quad in the xz plane (normal +y), glTF uv u = (x + 1) / 2, v = (z + 1) / 2, one material.
Document quad_document(int material_count = 1) {
  Document doc;
  MeshDesc mesh{"quad", {}};
  PrimitiveDesc p;
  p.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  p.normals.assign(4, {0, 1, 0});
  for (const auto& q : p.positions) p.uvs.push_back({(q.x + 1) / 2, (q.z + 1) / 2});
  p.indices = {0, 2, 1, 0, 3, 2};
  p.material = 0;
  mesh.primitives.push_back(p);
  doc.meshes.push_back(mesh);
  for (int i = 0; i < material_count; ++i) doc.materials.push_back({.name = "m" + std::to_string(i)});
  NodeDesc node;
  node.name = "quad";
  node.mesh = 0;
  doc.nodes.push_back(node);
  doc.scene_nodes = {0};
  return doc;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GltfImport, ShowcaseMaterialsMapToGlintlabsModel) {
  const GltfAsset a = showcase();
  const Document doc = make_showcase_document();
  EXPECT_EQ(a.materials.size(), 5u);
  EXPECT_EQ(a.lights.size(), 3u);
  ASSERT_EQ(a.cameras.size(), 1u);
  EXPECT_EQ(a.cameras[0].name, "view");
  EXPECT_NEAR(a.cameras[0].camera.fov_y_degrees, 0.7 * 180 / M_PI, 1e-4);

  // Anisotropic dielectric: alpha_x = mix(r^2, 1, s^2) along the rotated tangent; f0 from ior and
  // KHR_materials_specular: min(((ior - 1) / (ior + 1))^2 colour, 1) factor.
  const Material& torus = material_named(a, "brushed-dielectric");
  const MaterialDesc& desc = doc.materials[2];
  ASSERT_EQ(desc.name, "brushed-dielectric");
  const float r2 = desc.roughness * desc.roughness, s = desc.anisotropy->x;
  EXPECT_NEAR(torus.alpha.y, r2, 1e-6);
  EXPECT_NEAR(torus.alpha.x, r2 + (1 - r2) * s * s, 1e-6);
  EXPECT_NEAR(torus.anisotropy_rotation, desc.anisotropy->y, 1e-6);
  const float f0_ior = std::pow((*desc.ior - 1) / (*desc.ior + 1), 2.0f);
  ASSERT_TRUE(torus.textures.has_value());  // its base colour is a texture
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(torus.textures->dielectric_f0[c], f0_ior * desc.specular->second[c] * desc.specular->first, 1e-6);

  const Material& lantern = material_named(a, "lantern-glow");
  const MaterialDesc& glow = doc.materials[3];
  EXPECT_NEAR(lantern.emission.r, glow.emissive.r * *glow.emissive_strength, 1e-5);

  const Material& gold = material_named(a, "dimpled-gold");
  ASSERT_NE(gold.normal_map, nullptr);
  EXPECT_FALSE(gold.textures.has_value()) << "factors only: no per-texel variant";
}

TEST(GltfImport, UvAndTextureRowsAreFlippedToVUpAndTransformsConjugated) {
  const Document doc = make_showcase_document();
  const GltfAsset a = showcase();
  // The ground: the first primitive, uv (u, 1 - v) of what was written.
  const GltfPrimitive& ground = a.primitives[0];
  const PrimitiveDesc& written = doc.meshes[0].primitives[0];
  ASSERT_EQ(ground.mesh->uvs.size(), written.uvs.size());
  for (std::size_t i = 0; i < written.uvs.size(); ++i) {
    EXPECT_EQ(ground.mesh->uvs[i].x, written.uvs[i].x);
    EXPECT_NEAR(ground.mesh->uvs[i].y, 1.0f - written.uvs[i].y, 1e-6);
  }
  // Texture rows bottom first: internal row 0 is the image's last row.
  const Material& m = a.materials[static_cast<std::size_t>(ground.material)];
  ASSERT_TRUE(m.textures.has_value());
  const MaterialTexture& t = *m.textures->base_color_texture.texture;
  const Image8& image = doc.images[static_cast<std::size_t>(doc.materials[0].base_color_texture.image)];
  ASSERT_EQ(t.width, image.width);
  for (int x = 0; x < image.width; ++x)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(t.rgba[static_cast<std::size_t>(x) * 4 + k],
                image.rgba[(static_cast<std::size_t>(image.height - 1) * image.width + x) * 4 + k]);
  EXPECT_TRUE(t.srgb);
  EXPECT_FALSE(m.textures->metallic_roughness_texture.texture->srgb);
  // The transform: glintlab's (u, 1 - v) goes where glTF's maps (u, v), flipped.
  const TextureTransform tt = *doc.materials[0].base_color_texture.transform;
  for (const glm::vec2 uv : {glm::vec2(0.1f, 0.2f), glm::vec2(0.7f, 0.4f), glm::vec2(-1.5f, 2.5f)}) {
    const float c = std::cos(tt.rotation), s = std::sin(tt.rotation);
    const glm::vec2 scaled = uv * tt.scale;
    const glm::vec2 gltf_st = glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + tt.offset;
    const glm::vec3 ours = m.textures->base_color_texture.transform * glm::vec3(uv.x, 1.0f - uv.y, 1.0f);
    EXPECT_NEAR(ours.x, gltf_st.x, 1e-5);
    EXPECT_NEAR(ours.y, 1.0f - gltf_st.y, 1e-5);
  }
}

TEST(GltfImport, FileTangentsAreKeptAndMissingOnesBuiltAlongUpInTheImage) {
  const Document doc = make_showcase_document();
  const GltfAsset a = showcase();
  for (const GltfPrimitive& p : a.primitives) {
    ASSERT_EQ(p.mesh->tangents.size(), p.mesh->positions.size()) << p.mesh_name;
    // Every frame: the bitangent w cross(n, t) runs along +v of glintlab's uv (up in the image).
    int agree = 0, total = 0;
    for (std::size_t i = 0; i + 2 < p.mesh->indices.size(); i += 3) {
      const auto i0 = p.mesh->indices[i], i1 = p.mesh->indices[i + 1], i2 = p.mesh->indices[i + 2];
      const glm::vec3 e1 = p.mesh->positions[i1] - p.mesh->positions[i0], e2 = p.mesh->positions[i2] - p.mesh->positions[i0];
      const glm::vec2 d1 = p.mesh->uvs[i1] - p.mesh->uvs[i0], d2 = p.mesh->uvs[i2] - p.mesh->uvs[i0];
      const float det = d1.x * d2.y - d2.x * d1.y;
      if (std::abs(det) < 1e-12f) continue;
      const glm::vec3 dpdv = (d1.x * e2 - d2.x * e1) / det;
      const glm::vec4 t = p.mesh->tangents[i0];
      const glm::vec3 b = t.w * glm::cross(p.mesh->normals[i0], glm::vec3(t));
      ++total;
      agree += glm::dot(b, dpdv) > 0.0f;
    }
    EXPECT_GE(agree, total * 99 / 100) << p.mesh_name << "#" << p.primitive;
  }
  // The sphere's TANGENT is the file's, unchanged.
  const auto& sphere = doc.meshes[1].primitives[0];
  ASSERT_FALSE(sphere.tangents.empty());
  for (const GltfPrimitive& p : a.primitives)
    if (p.mesh_name == doc.meshes[1].name)
      for (std::size_t i = 0; i < sphere.tangents.size(); i += 97) {
        EXPECT_NEAR(p.mesh->tangents[i].x, sphere.tangents[i].x, 1e-6);
        EXPECT_EQ(p.mesh->tangents[i].w, sphere.tangents[i].w);
      }
}

TEST(GltfImport, LightsAndCamerasAreInTheFilesWorld) {
  const GltfAsset a = showcase();
  std::map<std::string, int> kinds;
  for (const Light& l : a.lights) ++kinds[l.kind->id];
  EXPECT_EQ(kinds["directional"], 1);
  EXPECT_EQ(kinds["point"], 1);
  EXPECT_EQ(kinds["spot"], 1);
  for (const Light& l : a.lights) {
    if (l.kind->id == "spot") {
      EXPECT_NEAR(l.inner_angle_degrees, 0.3 * 180 / M_PI, 1e-3);
      EXPECT_NEAR(l.outer_angle_degrees, 0.5 * 180 / M_PI, 1e-3);
      EXPECT_NEAR(l.colour.b, 15.0f, 1e-4) << "colour x intensity";
    }
    if (l.kind->id == "directional") {
      EXPECT_LT(l.direction.y, -0.5f) << "the sun shines down";
    }
  }
  const Camera& c = a.cameras[0].camera;
  EXPECT_NEAR(glm::distance(c.position, glm::vec3(0.3f, 1.7f, 4.2f)), 0.0f, 1e-4f) << "the camera node's place";
  EXPECT_GT(glm::dot(glm::normalize(c.target - c.position), glm::normalize(glm::vec3(0, 0.5f, 0) - c.position)), 0.95f);
}

TEST(GltfImport, UnimplementedExtensionsAreNamedInWarningsAndRequiredOnesRejected) {
  Document doc = quad_document();
  doc.extra_extensions_used = {"KHR_materials_clearcoat"};
  doc.materials[0].extra_extensions = {"KHR_materials_sheen"};
  doc.lights.push_back({.name = "lamp", .type = "point", .range = 5.0f});
  NodeDesc lamp;
  lamp.name = "lamp";
  lamp.light = 0;
  doc.nodes.push_back(lamp);
  doc.scene_nodes.push_back(1);
  const GltfAsset a = import_glb(encode_glb(doc), "quad.glb");
  std::string all;
  for (const auto& w : a.warnings) all += w + "\n";
  EXPECT_NE(all.find("KHR_materials_clearcoat"), std::string::npos) << all;
  EXPECT_NE(all.find("KHR_materials_sheen"), std::string::npos) << all;
  EXPECT_NE(all.find("quad.glb"), std::string::npos) << all;
  EXPECT_NE(all.find("light ranges are ignored"), std::string::npos) << all;

  ScratchDirectory dir;
  std::string json = encode_gltf_json(quad_document());
  json.insert(1, "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],");
  std::ofstream(dir / "draco.gltf") << json;
  const std::string e = error_of([&] { import_gltf(dir / "draco.gltf"); });
  EXPECT_NE(e.find("draco.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("requires extension KHR_draco_mesh_compression"), std::string::npos) << e;
}

TEST(GltfImport, DeepHierarchiesLoadAndCyclesAreRejectedNamingTheNode) {
  Document doc = quad_document();
  doc.nodes.clear();
  for (int i = 0; i < 300; ++i) {  // a chain far deeper than the old limit of 64
    NodeDesc n;
    n.name = "n" + std::to_string(i);
    n.translation = {0.01f, 0, 0};
    if (i + 1 < 300) n.children = {i + 1};
    else n.mesh = 0;
    doc.nodes.push_back(n);
  }
  const GltfAsset a = import_glb(encode_glb(doc), "deep.glb");
  ASSERT_EQ(a.primitives.size(), 1u);
  EXPECT_NEAR(a.primitives[0].transform[3][0], 3.0f, 1e-3);

  ScratchDirectory dir;
  std::ofstream(dir / "cycle.gltf") << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                                       R"("nodes":[{"children":[1]},{"children":[0]}]})";
  const std::string e = error_of([&] { import_gltf(dir / "cycle.gltf"); });
  EXPECT_NE(e.find("cycle.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("node 0 is reached twice"), std::string::npos) << e;
}

TEST(GltfImport, SceneFilesOverrideMaterialsByMeshAndPrimitiveAndChooseCameras) {
  ScratchDirectory dir;
  write_gltf(dir / "model.glb", make_showcase_document());
  auto scene_with = [&](const std::string& shape_keys, const std::string& more = "") {
    std::ofstream(dir / "s.toml") << "[[material]]\nname = \"glints\"\ntype = \"glinty\"\n" << more
                                  << "[[shape]]\ntype = \"mesh\"\nfile = \"model.glb\"\n" << shape_keys;
    return load_scene((dir / "s.toml").string());
  };
  const Scene plain = scene_with("");
  EXPECT_EQ(plain.materials.size(), 6u) << "the scene's glinty one and the file's five";
  EXPECT_EQ(plain.lights.size(), 3u) << "the file's lights light the scene";
  EXPECT_EQ(plain.camera.fov_y_degrees, showcase().cameras[0].camera.fov_y_degrees) << "the file's camera";

  const Document doc = make_showcase_document();
  const std::string sphere = doc.meshes[1].name;
  const Scene over = scene_with("materials = { \"" + sphere + "\" = \"glints\" }\nlights = false\n",
                                "[[light]]\ntype = \"point\"\nposition = [0, 3, 0]\n");
  int glinty = 0;
  for (const Shape& s : over.shapes) glinty += s.material == 0;
  EXPECT_EQ(glinty, 1) << "only the sphere";
  EXPECT_EQ(over.lights.size(), 1u) << "lights = false: only the scene's";

  const std::string lantern = doc.meshes[3].name;
  const Scene one = scene_with("materials = { \"" + lantern + "#1\" = \"glints\" }\n");
  glinty = 0;
  for (const Shape& s : one.shapes) glinty += s.material == 0;
  EXPECT_EQ(glinty, 1) << "one primitive of the lantern";

  const Scene all = scene_with("material = \"glints\"\n");
  EXPECT_EQ(all.materials.size(), 1u) << "every primitive overridden: none of the file's is added";

  const std::string e = error_of([&] { scene_with("materials = { \"helmet\" = \"glints\" }\n"); });
  EXPECT_NE(e.find("materials"), std::string::npos) << e;
  EXPECT_NE(e.find("\"helmet\" names no mesh"), std::string::npos) << e;
  EXPECT_NE(e.find(sphere), std::string::npos) << "lists the meshes: " << e;

  const Scene chosen = scene_with("", "[camera]\ngltf_camera = \"view\"\nfov = 20\n");
  EXPECT_EQ(chosen.camera.fov_y_degrees, 20.0f);
  EXPECT_EQ(chosen.camera.position, plain.camera.position);
  const std::string e2 = error_of([&] { scene_with("", "[camera]\ngltf_camera = \"nope\"\n"); });
  EXPECT_NE(e2.find("gltf_camera"), std::string::npos) << e2;
  EXPECT_NE(e2.find("view"), std::string::npos) << "lists the cameras: " << e2;
}

TEST(GltfImport, MaterialLimitIsAnErrorCountingTheFilesMaterials) {
  ScratchDirectory dir;
  Document doc = quad_document(kMaxMaterials + 1);
  // One primitive per material, so every one is used.
  for (int i = 1; i <= kMaxMaterials; ++i) {
    PrimitiveDesc p = doc.meshes[0].primitives[0];
    p.material = i;
    doc.meshes[0].primitives.push_back(p);
  }
  write_gltf(dir / "many.glb", doc);
  std::ofstream(dir / "s.toml") << "[[shape]]\ntype = \"mesh\"\nfile = \"many.glb\"\n[[light]]\ntype = \"point\"\nposition = [0, 1, 0]\n";
  const std::string e = error_of([&] { load_scene((dir / "s.toml").string()); });
  EXPECT_NE(e.find(std::to_string(kMaxMaterials + 1) + " materials (" + std::to_string(kMaxMaterials + 1) + " from glTF files)"),
            std::string::npos) << e;
  EXPECT_NE(e.find("at most " + std::to_string(kMaxMaterials)), std::string::npos) << e;
}

TEST(GltfImport, BrokenFilesAreInputErrorsNamingTheFile) {
  ScratchDirectory dir;
  std::ofstream(dir / "junk.glb") << "not a glb";
  EXPECT_NE(error_of([&] { import_gltf(dir / "junk.glb"); }).find("junk.glb"), std::string::npos);
  std::ofstream(dir / "huge.gltf")
      << R"({"asset":{"version":"2.0"},"images":[{"uri":"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAATiAAAABkCAAAAABG5l+7AAAAC0lEQVR4nGNggAEAAAoAAX+AdF4AAAAASUVORK5CYII="}]})";
  const std::string e = error_of([&] { import_gltf(dir / "huge.gltf"); });
  EXPECT_NE(e.find("huge.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("20000x100; allowed: 1 to 16384"), std::string::npos) << "checked before decoding: " << e;
  EXPECT_NE(error_of([&] { import_gltf(dir / "missing.glb"); }).find("missing.glb"), std::string::npos);
}

TEST(GltfImport, UrisThatAreNotRegularFilesAreInputErrors) {
  // Found with fuzz/fuzz_gltf.cpp (docs/fuzzing.md, finding 11): tinygltf's own reader took a
  // directory's size as LLONG_MAX (std::bad_alloc) and blocked on a FIFO.
  ScratchDirectory dir;
  std::string json = encode_gltf_json(quad_document());
  const auto at = json.find("data:application/octet-stream;base64,");
  ASSERT_NE(at, std::string::npos);
  const auto end = json.find('"', at);
  ASSERT_EQ(mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
  for (const std::string uri : {".", "fifo.bin", "missing.bin"}) {
    std::ofstream(dir / "m.gltf") << json.substr(0, at) + uri + json.substr(end);
    const std::string e = error_of([&] { import_gltf(dir / "m.gltf"); });
    EXPECT_NE(e.find("m.gltf"), std::string::npos) << uri << ": " << e;
  }
}

TEST(GltfImport, ValuesThatWouldBecomeNanOrDefaultsAreInputErrorsNamingTheElement) {
  // Round three of hostile input: each of these rendered NaN (exit 1) or was silently replaced.
  ScratchDirectory dir;
  const std::string png_1x1 =
      "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGNo6GgAAAMEAYFL09IQAAAAAElFTkSuQmCC";
  auto textured = [&] {
    nlohmann::json doc = nlohmann::json::parse(encode_gltf_json(quad_document()));
    doc["images"] = {{{"uri", png_1x1}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_anisotropy"};
    return doc;
  };
  auto expect_error = [&](const nlohmann::json& doc, std::initializer_list<const char*> fragments) {
    std::ofstream(dir / "bad.gltf") << doc.dump();
    const std::string e = error_of([&] { import_gltf(dir / "bad.gltf"); });
    ASSERT_FALSE(e.empty()) << doc.dump().substr(0, 200);
    for (const char* f : {"bad.gltf"}) EXPECT_NE(e.find(f), std::string::npos) << e;
    for (const char* f : fragments) EXPECT_NE(e.find(f), std::string::npos) << "'" << f << "' not in: " << e;
  };
  ASSERT_EQ(error_of([&] {
              std::ofstream(dir / "good.gltf") << textured().dump();
              import_gltf(dir / "good.gltf");
            }),
            "");
  nlohmann::json doc = textured();
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
      {"offset", {1e308, 0}}};
  expect_error(doc, {"KHR_texture_transform offset[0]", "1e+308", "-1e+06 to 1e+06"});
  doc = textured();
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
      {"scale", {1e38, 1}}};
  expect_error(doc, {"scale[0]", "1e+38"});
  doc = textured();
  doc["materials"][0]["extensions"]["KHR_materials_anisotropy"] = {{"anisotropyStrength", 0.5},
                                                                   {"anisotropyRotation", 1e308}};
  expect_error(doc, {"anisotropyRotation", "1e+308"});
  doc = textured();
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = "red";
  expect_error(doc, {"materials[0].pbrMetallicRoughness.baseColorFactor", "\"red\"", "an array of 4 numbers"});
  doc = textured();
  doc["textures"][0]["sampler"] = 9;
  expect_error(doc, {"texture 0 refers to sampler 9", "the file has 0"});
  doc = textured();
  doc["asset"]["version"] = "3.0";
  expect_error(doc, {"asset version \"3.0\"", "2.x"});
  doc = textured();
  doc["images"][0]["uri"] = "data:image/ktx2;base64,q0tUWCAyMLsNChoKAAAAAAAAAAAAAAAAAAAAAA==";
  expect_error(doc, {"KTX2", "KHR_texture_basisu"});
  // A TANGENT along the NORMAL (+y) leaves no tangent frame.
  Document along = quad_document();
  along.meshes[0].primitives[0].tangents.assign(4, glm::vec4(0, 1, 0, 1));
  std::ofstream(dir / "tangent.gltf") << encode_gltf_json(along);
  const std::string e = error_of([&] { import_gltf(dir / "tangent.gltf"); });
  EXPECT_NE(e.find("(TANGENT) element 0 is zero or parallel to its NORMAL"), std::string::npos) << e;
}
