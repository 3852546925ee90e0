// Hostile mesh input (issue 13): every out-of-range index and non-finite value in an OBJ or glTF
// file is an InputError naming the file, the line or element, the value and what is allowed,
// instead of a crash or a silently broken mesh. Each case is a small file written by the test.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/mesh_io.hpp"
#include "scene/scene_loader.hpp"
#include "scratch_directory.hpp"
#include "test_scenes.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// Three positions, one normal, one uv: a valid triangle is `f 1/1/1 2/1/1 3/1/1`.
const std::string kObjLists = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n";

std::filesystem::path write_file(const ScratchDirectory& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string mesh_error(const std::filesystem::path& path) {
  try {
    load_mesh_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_mesh_error(const std::filesystem::path& path, std::initializer_list<std::string> fragments) {
  const std::string msg = mesh_error(path);
  ASSERT_FALSE(msg.empty()) << "no error for " << path;
  EXPECT_NE(msg.find(path.string()), std::string::npos) << msg;
  for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t present = std::min<std::size_t>(3, bytes.size() - i);  // bytes in this group
    unsigned v = 0;
    for (std::size_t k = 0; k < 3; ++k) v = (v << 8) | (k < present ? bytes[i + k] : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= present ? kDigits[(v >> (18 - 6 * k)) & 63u] : '=';
  }
  return out;
}

// A one-triangle glTF with its buffer inline: 3 float positions, then 3 uint16 indices.
std::string triangle_gltf(const std::vector<float>& positions, const std::vector<std::uint16_t>& indices) {
  std::vector<unsigned char> bytes(positions.size() * 4 + indices.size() * 2);
  std::memcpy(bytes.data(), positions.data(), positions.size() * 4);
  std::memcpy(bytes.data() + positions.size() * 4, indices.data(), indices.size() * 2);
  const auto n = std::to_string(positions.size() / 3);
  const auto pos_bytes = std::to_string(positions.size() * 4);
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
         R"("buffers":[{"byteLength":)" + std::to_string(bytes.size()) +
         R"(,"uri":"data:application/octet-stream;base64,)" + base64(bytes) + R"("}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + pos_bytes +
         R"(},{"buffer":0,"byteOffset":)" + pos_bytes + R"(,"byteLength":)" + std::to_string(indices.size() * 2) +
         R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" + n +
         R"(,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":)" +
         std::to_string(indices.size()) + R"(,"type":"SCALAR"}]})";
}

}  // namespace

TEST(HostileMeshes, ValidObjWithAbsoluteAndRelativeIndicesLoads) {
  ScratchDirectory dir;
  const Mesh m = load_mesh_file(write_file(dir, "ok.obj", kObjLists + "f 1/1/1 2/1/1 3/1/1\nf -3/-1/-1 -2/-1/-1 -1/-1/-1\n"));
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.indices.size(), 6u);
}

TEST(HostileMeshes, ObjNormalIndexOutOfRangeNamesLineAndValue) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "n.obj", kObjLists + "f 1/1/1 2/1/2 3/1/1\n"),
                    {":6:", "normal index 2", "allowed: 1 to 1"});
}

TEST(HostileMeshes, ObjUvIndexOutOfRangeNamesLineAndValue) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "uv.obj", kObjLists + "f 1/1/1 2/9/1 3/1/1\n"), {":6:", "uv index 9", "allowed: 1 to 1"});
}

TEST(HostileMeshes, ObjPositionIndexOnePastTheEndIsRejected) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "p.obj", kObjLists + "f 1 2 4\n"), {":6:", "position index 4", "allowed: 1 to 3"});
}

TEST(HostileMeshes, ObjNegativeIndexBeforeTheFirstLineIsRejected) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "neg.obj", kObjLists + "f -1 -2 -4\n"), {":6:", "position index -4", "allowed: -1 to -3"});
  expect_mesh_error(write_file(dir, "negn.obj", kObjLists + "f 1//-2 2//-1 3//-1\n"),
                    {":6:", "normal index -2", "allowed: -1 to -1"});
}

TEST(HostileMeshes, ObjZeroIndexIsRejected) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "zero.obj", kObjLists + "f 0 1 2\n"), {":6:", "position index '0'"});
}

TEST(HostileMeshes, ObjNonFiniteValuesNameLineAndValue) {
  ScratchDirectory dir;
  expect_mesh_error(write_file(dir, "nan.obj", "v nan 0 0\n" + kObjLists + "f 1 2 3\n"), {":1:", "`v` value nan", "allowed"});
  // fuzz/fuzz_obj.cpp (docs/fuzzing.md, finding 15): tinyobjloader's exponent overflowed an int.
  expect_mesh_error(write_file(dir, "exponent.obj", "v 11e-2147483648391 0 0\n" + kObjLists + "f 1 2 3\n"),
                    {":1:", "11e-2147483648391", "exponents of at most 3 digits"});
  // finding 18: tinyobjloader casts a skin weight's joint id (`vw`) to int.
  expect_mesh_error(write_file(dir, "weights.obj", kObjLists + "vw 2147483.43 6e170 2\nf 1 2 3\n"),
                    {"`vw` value 6e170", "at most 1e+09"});
  // finding 19: a lone "\r" ends a line for tinyobjloader, so it ends one for the check too.
  expect_mesh_error(write_file(dir, "cr.obj", kObjLists + "g x\rvw 0 2214748956365 0.5\nf 1 2 3\n"),
                    {":7:", "`vw` value 2214748956365"});
  // finding 20: tinyobjloader reads a `vw` line to its end, past a '#'.
  expect_mesh_error(write_file(dir, "vw-comment.obj", kObjLists + "vw 1 1 # 502147483647\nf 1 2 3\n"),
                    {":6:", "`vw` value #"});
  expect_mesh_error(write_file(dir, "inf.obj", kObjLists + "vn inf 0 0\nf 1//2 2//1 3//1\n"), {":6:", "`vn` value inf"});
  expect_mesh_error(write_file(dir, "big.obj", kObjLists + "v 1e39 0 0\nf 1 2 3\n"), {":6:", "`v` value 1e39"});
  expect_mesh_error(write_file(dir, "uvnan.obj", kObjLists + "vt 0 -nan\nf 1 2 3\n"), {":6:", "`vt` value -nan"});
}

TEST(HostileMeshes, ObjErrorReachesTheSceneFileWithTheShapeKey) {
  ScratchDirectory dir;
  write_file(dir, "n.obj", kObjLists + "f 1/1/1 2/1/2 3/1/1\n");
  const auto scene = write_file(dir, "s.toml", TestScene::minimal().shape("mesh", "m", {{"file", "n.obj"}}).toml());
  try {
    load_scene(scene.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const char* f : {"s.toml", "'file'", "n.obj:6:", "normal index 2"})
      EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
  }
}

TEST(HostileMeshes, GltfIndexBeyondTheVertexCountIsRejected) {
  ScratchDirectory dir;
  EXPECT_EQ(load_mesh_file(write_file(dir, "ok.gltf", triangle_gltf({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}))).indices.size(), 3u);
  expect_mesh_error(write_file(dir, "idx.gltf", triangle_gltf({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 3})),
                    {"accessor 1", "element 2", "value 3", "allowed: 0 to 3 - 1"});
}

TEST(HostileMeshes, GltfNanPositionIsRejected) {
  ScratchDirectory dir;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expect_mesh_error(write_file(dir, "nan.gltf", triangle_gltf({0, 0, 0, 1, nan, 0, 0, 1, 0}, {0, 1, 2})),
                    {"accessor 0", "POSITION", "element 1", "nan", "allowed: finite"});
}

TEST(HostileMeshes, TubeWithCoincidentPointsNamesPoints) {
  const std::string text =
      TestScene::minimal().shape("tube", "m", {{"points", std::vector<glm::vec3>{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}}}}).toml();
  try {
    parse_scene(text, "tube.toml", ".");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const char* f : {"tube.toml", "key 'points'", "[1, 2, 3]", "at least two different points"})
      EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
    EXPECT_EQ(msg.find("'type'"), std::string::npos) << msg;
  }
}

TEST(HostileMeshes, ATubeTooLargeToGenerateNamesItsSizeBeforeAllocating) {
  // 5000 points x 1024 segments x 1025 vertices around are 5.2e9 vertices: std::bad_alloc (issue 13).
  std::vector<glm::vec3> points;
  for (int i = 0; i < 5000; ++i) points.emplace_back(0.01f * static_cast<float>(i), std::sin(0.1f * static_cast<float>(i)), 0.0f);
  const std::string text =
      TestScene::minimal().shape("tube", "m", {{"points", points}, {"segments", 1024}, {"sides", 1024}}).toml();
  try {
    parse_scene(text, "tube.toml", ".");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const char* f : {"tube.toml", "key 'points'", "5000 points x 1024 segments x 1025", "5246951425 vertices",
                          "allowed: at most 33554432"})
      EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
  }
  // The same points with the default segments and sides are a modest mesh.
  const std::string fine = TestScene::minimal().shape("tube", "m", {{"points", points}}).toml();
  EXPECT_EQ(parse_scene(fine, "tube.toml", ".").shapes.back().mesh->positions.size(), tube_vertex_count(5000, 16, 16));
}

// fuzz/fuzz_obj.cpp (docs/fuzzing.md): tinyobjloader read `mtllib ../../dev/zero` to no end (a
// hang growing memory); a FIFO blocks it forever. A library that is not a regular file is exit 2.
TEST(HostileMeshes, ObjMaterialLibraryThatIsNotARegularFileIsRejected) {
  const ScratchDirectory dir;
  ASSERT_EQ(mkfifo((dir / "fifo.mtl").c_str(), 0600), 0);
  expect_mesh_error(write_file(dir, "fifo.obj", "mtllib fifo.mtl\n" + kObjLists + "f 1 2 3\n"),
                    {":1:", "`mtllib` fifo.mtl", "not a regular file"});
  const auto dev_zero = std::filesystem::relative("/dev/zero", dir.path()).string();
  expect_mesh_error(write_file(dir, "zero.obj", kObjLists + "mtllib missing.mtl " + dev_zero + "\nf 1 2 3\n"),
                    {":6:", "`mtllib` " + dev_zero, "not a regular file"});
  std::filesystem::create_directory(dir / "directory.mtl");
  expect_mesh_error(write_file(dir, "dir.obj", "mtllib directory.mtl\n" + kObjLists + "f 1 2 3\n"), {":1:"});
  // A missing library is only a warning in tinyobjloader, and a regular one is read.
  write_file(dir, "ok.mtl", "newmtl a\nKd 1 1 1\n");
  EXPECT_EQ(load_mesh_file(write_file(dir, "ok.obj", "mtllib ok.mtl none.mtl\n" + kObjLists + "f 1 2 3\n")).indices.size(), 3u);
}
