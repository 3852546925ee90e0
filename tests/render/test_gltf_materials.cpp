// glTF materials in images: a normal map that encodes a tilt shades like a plane with that tilt
// (glTF's tangent frame: +X along +u, +Y up in the image; with the file's TANGENT or without,
// with mirrored uv); a textured material equals the material of its texel's value in every method
// and in the reference; emission adds to the total and not to the specular image; an anisotropy
// rotated by 90 degrees is the swapped roughness.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_fixture.hpp"
#include "scene/gltf/gltf_showcase.hpp"
#include "scene/gltf/gltf_writer.hpp"
#include "scratch_directory.hpp"
#include "shading/registry.hpp"

using namespace glintlab;
using namespace glintlab::gltf;
using namespace glintlab::test;

namespace {

constexpr int kWidth = 64, kHeight = 32;

/// A 2 x 2 quad centred at (cx, 0, 0) in the xz plane, normal +y, glTF uv u = (x - cx + 1) / 2
/// (mirrored: 1 - that), v = (z + 1) / 2 (so "up in the image", -v, is -z). With `tangents`, the
/// glTF frame: T = dP/du, w so that w cross(n, T) = -z.
PrimitiveDesc quad(float cx, bool mirrored, bool tangents, glm::vec3 normal, int material) {
  PrimitiveDesc p;
  p.positions = {{cx - 1, 0, -1}, {cx + 1, 0, -1}, {cx + 1, 0, 1}, {cx - 1, 0, 1}};
  p.normals.assign(4, normal);
  for (const auto& q : p.positions) {
    const float u = (q.x - cx + 1) / 2;
    p.uvs.push_back({mirrored ? 1 - u : u, (q.z + 1) / 2});
  }
  if (tangents) p.tangents.assign(4, mirrored ? glm::vec4(-1, 0, 0, -1) : glm::vec4(1, 0, 0, 1));
  p.indices = {0, 2, 1, 0, 3, 2};
  p.material = material;
  return p;
}

Document one_mesh(std::vector<PrimitiveDesc> primitives) {
  Document doc;
  doc.meshes.push_back({"quads", std::move(primitives)});
  NodeDesc node;
  node.name = "quads";
  node.mesh = 0;
  doc.nodes.push_back(node);
  doc.scene_nodes = {0};
  return doc;
}

/// Two quads seen from above: x < 0 and x > 0, lit by a directional light from the side.
/// The two quads of `doc`, seen from above, under a directional light. `showcase_lights` adds a
/// point light and a spot light below the quads, which do not light their upper sides: the light
/// kinds and counts of builtin:gltf-showcase, so that every program drawn here is one its
/// every-method test compiled (shared through the GL driver's shader cache, tests/test_costs.cmake).
Scene two_quads(const ScratchDirectory& dir, const Document& doc, bool showcase_lights = false) {
  write_gltf(dir / "quads.glb", doc);
  TestScene scene = TestScene()
                        .film(kWidth, kHeight)
                        .orthographic_camera({0, 10, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}, {"near", 1}, {"far", 20}})
                        .array_table("shape", {{"type", "mesh"}, {"file", (dir / "quads.glb").string()}})
                        .directional_light({-0.3, -1.0, -0.5}, 2.0);
  if (showcase_lights)
    scene.point_light({0, -3, 0}, 5).light("spot", {{"position", {0, -3, 0}}, {"direction", {0, -1, 0}}});
  return scene.scene();
}

/// Mean total (green) over the middle of the left or right half.
double half_mean(const Image& img, bool right) {
  double sum = 0;
  int n = 0;
  for (int y = kHeight / 4; y < 3 * kHeight / 4; ++y)
    for (int x = kWidth / 8; x < 3 * kWidth / 8; ++x) {
      sum += img.at(right ? x + kWidth / 2 : x, y).g;
      ++n;
    }
  return sum / n;
}

}  // namespace

TEST(GltfMaterials, NormalMapTiltShadesLikeTheTiltedPlaneInGltfsFrame) {
  ScratchDirectory dir;
  const float a = 0.5f;  // the tilt, radians
  for (const bool along_y : {false, true})
    for (const bool mirrored : {false, true})
      for (const bool tangents : {false, true}) {
        // The map's tangent-space normal, tilted towards +X (right in the image) or +Y (up).
        const glm::vec3 tilt = along_y ? glm::vec3(0, std::sin(a), std::cos(a)) : glm::vec3(std::sin(a), 0, std::cos(a));
        // The normal the 8-bit map holds: 2 round(255 (n / 2 + 1 / 2)) / 255 - 1, renormalised.
        const glm::vec3 mapped = glm::normalize(2.0f * glm::round(255.0f * (tilt * 0.5f + 0.5f)) / 255.0f - 1.0f);
        // Where that is on the quad: +X along dP/du (+x, or -x when mirrored), +Y up in the image (-z).
        const glm::vec3 t(mirrored ? -1 : 1, 0, 0), b(0, 0, -1), n(0, 1, 0);
        const glm::vec3 expected = mapped.x * t + mapped.y * b + mapped.z * n;
        const glm::vec3 wrong = mapped.x * t - mapped.y * b + mapped.z * n - (along_y ? glm::vec3(0) : 2.0f * mapped.x * t);
        for (const glm::vec3 twin_normal : {expected, wrong}) {
          Document doc = one_mesh({quad(-1, mirrored, tangents, n, 0), quad(1, mirrored, tangents, twin_normal, 1)});
          doc.images.push_back(make_normal_image(8, 8, [&](glm::vec2) { return tilt; }));
          MaterialDesc m{.name = "mapped", .base_color = glm::vec4(0.8f), .metallic = 0.5f, .roughness = 0.45f};
          MaterialDesc plain = m;
          plain.name = "plain";
          m.normal_texture.image = 0;
          doc.materials = {m, plain};
          SceneFixture f(two_quads(dir, doc));
          const Frame img = f.method("conventional");
          const double mapped_mean = half_mean(img.total, false), twin_mean = half_mean(img.total, true);
          const double difference = std::abs(mapped_mean - twin_mean) / twin_mean;
          const std::string what = std::string(along_y ? "tilt along +Y" : "tilt along +X") +
                                   (mirrored ? ", mirrored uv" : "") + (tangents ? ", file TANGENT" : ", built frame");
          if (twin_normal == expected)
            EXPECT_LT(difference, 2e-3) << what << ": " << mapped_mean << " vs " << twin_mean;
          else
            EXPECT_GT(difference, 0.1) << what << ": the flipped tilt must look different";
        }
      }
}

TEST(GltfMaterials, TexturedMaterialEqualsTheMaterialOfItsTexelsInEveryMethodAndTheReference) {
  // Left: base colour factor x texel, metallic and roughness from uniform textures; right: the
  // same values as factors without textures. 8-bit texels k / 255 are exact in both; the base
  // colour's texels are 0 and 255, whose sRGB decoding is exact on any driver (with texels
  // (200, 120, 60) llvmpipe's decoding made the image 0.4% brighter than the sRGB formula's).
  ScratchDirectory dir;
  const glm::vec3 factor(0.6f, 0.5f, 0.3f), colour(1.0f, 1.0f, 0.0f);
  const float roughness = 100 / 255.0f, metallic = 150 / 255.0f;
  Document doc = one_mesh({quad(-1, false, false, {0, 1, 0}, 0), quad(1, false, false, {0, 1, 0}, 1)});
  doc.images.push_back(make_image(4, 4, [&](glm::vec2) { return glm::vec4(colour, 1); }));
  doc.images.push_back(make_image(4, 4, [&](glm::vec2) { return glm::vec4(0, roughness, metallic, 1); }));
  MaterialDesc textured{.name = "textured", .base_color = glm::vec4(factor, 1)};
  textured.base_color_texture.image = 0;
  textured.metallic_roughness_texture.image = 1;
  MaterialDesc factors{.name = "factors", .base_color = glm::vec4(factor * colour, 1), .metallic = metallic,
                       .roughness = roughness};
  doc.materials = {textured, factors};
  SceneFixture f(two_quads(dir, doc, true));
  for (const auto& m : all_methods()) {
    const Frame img = f.method(m.id);
    const double left = half_mean(img.total, false), right = half_mean(img.total, true);
    EXPECT_NEAR(left / right, 1.0, 2e-3) << m.id;
    EXPECT_GT(half_mean(img.specular, false), 0.0) << m.id;
  }
  const Frame ref = f.reference(4);
  EXPECT_NEAR(half_mean(ref.total, false) / half_mean(ref.total, true), 1.0, 2e-3) << "reference";
}

TEST(GltfMaterials, EmissionAddsToTheTotalAndNotToTheSpecularImage) {
  ScratchDirectory dir;
  Document doc = one_mesh({quad(-1, false, false, {0, 1, 0}, 0), quad(1, false, false, {0, 1, 0}, 1)});
  doc.images.push_back(make_image(4, 4, [](glm::vec2) { return glm::vec4(1, 1, 1, 1); }));
  MaterialDesc glowing{.name = "glowing", .base_color = glm::vec4(0.5f), .metallic = 0, .roughness = 0.5f};
  MaterialDesc plain = glowing;
  plain.name = "plain";
  glowing.emissive = glm::vec3(0.25f);
  glowing.emissive_strength = 4.0f;
  glowing.emissive_texture.image = 0;  // white: the factor alone, through the textured variant
  doc.materials = {glowing, plain};
  SceneFixture f(two_quads(dir, doc, true));  // the textured test's programs (test_costs.cmake)
  for (const std::string id : {"conventional", "lean", "podee"}) {
    const Frame img = f.method(id);
    EXPECT_NEAR(half_mean(img.total, false) - half_mean(img.total, true), 1.0, 1e-4) << id << ": 0.25 x 4";
    EXPECT_NEAR(half_mean(img.specular, false), half_mean(img.specular, true), 1e-6) << id;
  }
}

TEST(GltfMaterials, AnisotropyRotatedByAQuarterTurnIsTheSwappedRoughness) {
  ScratchDirectory dir;
  Document doc = one_mesh({quad(-1, false, true, {0, 1, 0}, 0), quad(1, false, true, {0, 1, 0}, 1)});
  MaterialDesc turned{.name = "turned", .base_color = glm::vec4(0.9f), .metallic = 1, .roughness = 0.3f};
  turned.anisotropy = glm::vec2(0.8f, 0.5f * 3.14159265f);
  doc.materials = {turned, turned};
  doc.materials[1].name = "straight";
  doc.materials[1].anisotropy = glm::vec2(0.8f, 0.0f);
  Scene scene = two_quads(dir, doc);
  // The straight material with its two alphas swapped must equal the turned one.
  ASSERT_EQ(scene.materials.size(), 2u);
  std::swap(scene.materials[1].alpha.x, scene.materials[1].alpha.y);
  SceneFixture f(scene);
  const Frame img = f.method("conventional");
  EXPECT_NEAR(half_mean(img.specular, false) / half_mean(img.specular, true), 1.0, 1e-3);
  // And the unswapped one differs: the anisotropy is visible under this light.
  std::swap(scene.materials[1].alpha.x, scene.materials[1].alpha.y);
  SceneFixture g(scene);
  const Frame img2 = g.method("conventional");
  EXPECT_GT(std::abs(half_mean(img2.specular, false) / half_mean(img2.specular, true) - 1.0), 0.05);
}
