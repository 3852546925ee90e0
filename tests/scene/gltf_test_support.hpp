#pragma once
// Reading glintlab's own glTF files back with TinyGLTF's loader (not the writer's code): the
// glTF tests check what a third-party viewer would see.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace glintlab::test {

inline tinygltf::Model load_glb(const std::vector<std::uint8_t>& bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()));
  EXPECT_TRUE(ok) << err;
  EXPECT_EQ(err, "");
  EXPECT_EQ(warn, "");
  return model;
}

inline tinygltf::Model load_gltf_file(const std::filesystem::path& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
  EXPECT_TRUE(ok) << err;
  EXPECT_EQ(err, "");
  EXPECT_EQ(warn, "");
  return model;
}

/// An accessor's elements as T (float vectors), honouring the view's byteStride.
template <typename T>
std::vector<T> read_accessor(const tinygltf::Model& model, int index) {
  const auto& accessor = model.accessors.at(static_cast<std::size_t>(index));
  const auto& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const auto& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : sizeof(T);
  std::vector<T> out(accessor.count);
  for (std::size_t i = 0; i < accessor.count; ++i) {
    const std::size_t at = view.byteOffset + accessor.byteOffset + i * stride;
    EXPECT_LE(at + sizeof(T), buffer.size());
    if (at + sizeof(T) <= buffer.size()) std::memcpy(&out[i], buffer.data() + at, sizeof(T));
  }
  return out;
}

inline std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index) {
  const auto& accessor = model.accessors.at(static_cast<std::size_t>(index));
  std::vector<std::uint32_t> out;
  if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
    for (auto i : read_accessor<std::uint16_t>(model, index)) out.push_back(i);
  } else {
    EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    out = read_accessor<std::uint32_t>(model, index);
  }
  return out;
}

inline float number(const tinygltf::Value& object, const std::string& key) {
  EXPECT_TRUE(object.Has(key)) << key;
  return static_cast<float>(object.Get(key).GetNumberAsDouble());
}

}  // namespace glintlab::test
