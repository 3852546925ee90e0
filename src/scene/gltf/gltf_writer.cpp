#include "scene/gltf/gltf_writer.hpp"

#include <stb/stb_image_write.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "scene/gltf/gltf_document_check.hpp"

namespace glintlab::gltf {

namespace {

constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;

std::vector<double> to_doubles(const float* values, int count) {
  return {values, values + count};
}
std::vector<double> to_doubles(glm::vec3 v) { return {v.x, v.y, v.z}; }
std::vector<double> to_doubles(glm::vec4 v) { return {v.x, v.y, v.z, v.w}; }

tinygltf::Value number_array(const std::vector<double>& values) {
  tinygltf::Value::Array array;
  for (double v : values) array.emplace_back(v);
  return tinygltf::Value(std::move(array));
}

/// Appends to buffer 0 and describes what was appended. Every view starts on a 4-byte boundary
/// (glTF 2.0, 3.6.2.4: accessor offsets must be multiples of their component size, and a GLB's
/// BIN chunk is 4-byte aligned), so the padding goes before the view, never inside it.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) {
    if (model_.buffers.empty()) model_.buffers.emplace_back();
  }

  int add_view(const void* data, std::size_t bytes, int target, int stride) {
    auto& buffer = model_.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    view.byteStride = static_cast<std::size_t>(stride);  // 0: not written (tightly packed)
    const auto* p = static_cast<const std::uint8_t*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model_.bufferViews.push_back(std::move(view));
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  /// A float vertex attribute in its own strided view (byteStride = element size).
  template <typename Vec>
  int add_attribute(const std::vector<Vec>& values, int type, bool with_bounds) {
    constexpr int components = Vec::length();
    const int view = add_view(values.data(), values.size() * sizeof(Vec), kArrayBuffer,
                              static_cast<int>(sizeof(Vec)));
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = values.size();
    if (with_bounds) {  // required on POSITION (3.7.2.1)
      Vec lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
      for (const Vec& v : values) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
      accessor.minValues = to_doubles(&lo[0], components);
      accessor.maxValues = to_doubles(&hi[0], components);
    }
    model_.accessors.push_back(std::move(accessor));
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  /// Indices as unsigned short where every index fits below 65535 (that value is reserved as a
  /// primitive restart, 3.7.2.1), unsigned int otherwise. Index views have no byteStride.
  int add_indices(const std::vector<std::uint32_t>& indices, std::size_t vertex_count) {
    tinygltf::Accessor accessor;
    accessor.count = indices.size();
    accessor.type = TINYGLTF_TYPE_SCALAR;
    if (vertex_count <= 65535) {
      std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
      accessor.bufferView = add_view(narrow.data(), narrow.size() * 2, kElementArrayBuffer, 0);
    } else {
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
      accessor.bufferView = add_view(indices.data(), indices.size() * 4, kElementArrayBuffer, 0);
    }
    model_.accessors.push_back(std::move(accessor));
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& model_;
};

void write_png_chunk(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* p = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

std::vector<std::uint8_t> encode_png(const Image8& image) {
  std::vector<std::uint8_t> png;
  if (!stbi_write_png_to_func(write_png_chunk, &png, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4))
    throw RuntimeFailure("glTF writer: cannot encode a " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " PNG");
  return png;
}

/// Collects extensionsUsed in the order of first use (deterministic output).
class ExtensionList {
 public:
  void add(const std::string& name) {
    if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
  }
  [[nodiscard]] const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
};

/// Texture i shows image i through the one sampler, so a TextureRef's image index is the
/// texture index.
template <typename Info>
void set_texture(Info& info, const TextureRef& ref, ExtensionList& used) {
  info.index = ref.image;
  if (!ref.transform) return;
  const TextureTransform& t = *ref.transform;
  tinygltf::Value::Object transform;
  transform["offset"] = number_array({t.offset.x, t.offset.y});
  transform["rotation"] = tinygltf::Value(static_cast<double>(t.rotation));
  transform["scale"] = number_array({t.scale.x, t.scale.y});
  info.extensions["KHR_texture_transform"] = tinygltf::Value(std::move(transform));
  used.add("KHR_texture_transform");
}

tinygltf::Value object(std::initializer_list<std::pair<const std::string, tinygltf::Value>> members) {
  return tinygltf::Value(tinygltf::Value::Object(members));
}

tinygltf::Material make_material(const MaterialDesc& m, ExtensionList& used) {
  tinygltf::Material out;
  out.name = m.name;
  auto& pbr = out.pbrMetallicRoughness;
  pbr.baseColorFactor = to_doubles(m.base_color);
  pbr.metallicFactor = m.metallic;
  pbr.roughnessFactor = m.roughness;
  if (m.base_color_texture.image >= 0) set_texture(pbr.baseColorTexture, m.base_color_texture, used);
  if (m.metallic_roughness_texture.image >= 0)
    set_texture(pbr.metallicRoughnessTexture, m.metallic_roughness_texture, used);
  if (m.normal_texture.image >= 0) {
    set_texture(out.normalTexture, m.normal_texture, used);
    out.normalTexture.scale = m.normal_scale;
  }
  out.emissiveFactor = to_doubles(m.emissive);
  if (m.emissive_texture.image >= 0) set_texture(out.emissiveTexture, m.emissive_texture, used);
  out.doubleSided = m.double_sided;
  if (m.emissive_strength) {
    out.extensions["KHR_materials_emissive_strength"] =
        object({{"emissiveStrength", tinygltf::Value(static_cast<double>(*m.emissive_strength))}});
    used.add("KHR_materials_emissive_strength");
  }
  if (m.anisotropy) {
    out.extensions["KHR_materials_anisotropy"] =
        object({{"anisotropyStrength", tinygltf::Value(static_cast<double>(m.anisotropy->x))},
                {"anisotropyRotation", tinygltf::Value(static_cast<double>(m.anisotropy->y))}});
    used.add("KHR_materials_anisotropy");
  }
  if (m.ior) {
    out.extensions["KHR_materials_ior"] = object({{"ior", tinygltf::Value(static_cast<double>(*m.ior))}});
    used.add("KHR_materials_ior");
  }
  if (m.specular) {
    out.extensions["KHR_materials_specular"] =
        object({{"specularFactor", tinygltf::Value(static_cast<double>(m.specular->first))},
                {"specularColorFactor", number_array(to_doubles(m.specular->second))}});
    used.add("KHR_materials_specular");
  }
  for (const auto& name : m.extra_extensions) {
    out.extensions[name] = tinygltf::Value(tinygltf::Value::Object{});
    used.add(name);
  }
  return out;
}

tinygltf::Primitive make_primitive(const PrimitiveDesc& p, BufferBuilder& buffers) {
  tinygltf::Primitive out;
  out.mode = TINYGLTF_MODE_TRIANGLES;
  out.material = p.material;
  out.attributes["POSITION"] = buffers.add_attribute(p.positions, TINYGLTF_TYPE_VEC3, true);
  if (!p.normals.empty()) out.attributes["NORMAL"] = buffers.add_attribute(p.normals, TINYGLTF_TYPE_VEC3, false);
  if (!p.tangents.empty()) out.attributes["TANGENT"] = buffers.add_attribute(p.tangents, TINYGLTF_TYPE_VEC4, false);
  if (!p.uvs.empty()) out.attributes["TEXCOORD_0"] = buffers.add_attribute(p.uvs, TINYGLTF_TYPE_VEC2, false);
  out.indices = buffers.add_indices(p.indices, p.positions.size());
  return out;
}

tinygltf::Light make_light(const LightDesc& l) {
  tinygltf::Light out;
  out.name = l.name;
  out.type = l.type;
  out.color = to_doubles(l.colour);
  out.intensity = l.intensity;
  out.range = l.range.value_or(0.0f);  // TinyGLTF omits range <= 0 (= infinite)
  out.spot.innerConeAngle = l.inner_cone;
  out.spot.outerConeAngle = l.outer_cone;
  return out;
}

tinygltf::Camera make_camera(const CameraDesc& c) {
  tinygltf::Camera out;
  out.name = c.name;
  if (c.perspective) {
    out.type = "perspective";
    out.perspective.yfov = c.yfov;
    out.perspective.aspectRatio = c.aspect;  // TinyGLTF omits it when 0
    out.perspective.znear = c.znear;
    out.perspective.zfar = c.zfar;
  } else {
    out.type = "orthographic";
    out.orthographic.xmag = c.xmag;
    out.orthographic.ymag = c.ymag;
    out.orthographic.znear = c.znear;
    out.orthographic.zfar = c.zfar;
  }
  return out;
}

/// Default TRS components are left out; a matrix replaces all three (3.5.2: not both).
tinygltf::Node make_node(const NodeDesc& n) {
  tinygltf::Node out;
  out.name = n.name;
  out.mesh = n.mesh;
  out.camera = n.camera;
  out.children = n.children;
  if (n.light >= 0) out.extensions["KHR_lights_punctual"] = object({{"light", tinygltf::Value(n.light)}});
  if (n.matrix) {
    out.matrix = to_doubles(&(*n.matrix)[0][0], 16);  // both column-major
    return out;
  }
  if (n.translation != glm::vec3(0.0f)) out.translation = to_doubles(n.translation);
  if (n.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
    out.rotation = {n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w};
  if (n.scale != glm::vec3(1.0f)) out.scale = to_doubles(n.scale);
  return out;
}

tinygltf::Model make_model(const Document& doc) {
  check_document(doc);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "glintlab";
  BufferBuilder buffers(model);
  ExtensionList used;

  if (!doc.images.empty()) {
    tinygltf::Sampler sampler;  // trilinear, repeat: what a viewer would pick by default
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_REPEAT;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
    model.samplers.push_back(sampler);
  }
  for (std::size_t i = 0; i < doc.images.size(); ++i) {
    const auto png = encode_png(doc.images[i]);
    tinygltf::Image image;
    image.name = "image" + std::to_string(i);
    image.mimeType = "image/png";
    image.bufferView = buffers.add_view(png.data(), png.size(), 0, 0);  // no target: not vertex data
    model.images.push_back(std::move(image));
    tinygltf::Texture texture;
    texture.sampler = 0;
    texture.source = static_cast<int>(i);
    model.textures.push_back(texture);
  }
  for (const auto& m : doc.materials) model.materials.push_back(make_material(m, used));
  for (const auto& mesh : doc.meshes) {
    tinygltf::Mesh out;
    out.name = mesh.name;
    for (const auto& p : mesh.primitives) out.primitives.push_back(make_primitive(p, buffers));
    model.meshes.push_back(std::move(out));
  }
  for (const auto& l : doc.lights) model.lights.push_back(make_light(l));
  if (!doc.lights.empty()) used.add("KHR_lights_punctual");
  for (const auto& c : doc.cameras) model.cameras.push_back(make_camera(c));
  for (const auto& n : doc.nodes) model.nodes.push_back(make_node(n));
  if (!doc.scene_nodes.empty()) {  // a scene without nodes would be written as null
    tinygltf::Scene scene;
    scene.nodes = doc.scene_nodes;
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;
  }
  for (const auto& name : doc.extra_extensions_used) used.add(name);
  model.extensionsUsed = used.names();
  auto& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // byteLength a multiple of 4, as the BIN chunk
  if (buffer.empty()) model.buffers.clear();      // a buffer must not be empty (byteLength >= 1)
  return model;
}

std::string serialise(const Document& doc, bool binary) {
  const tinygltf::Model model = make_model(doc);
  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, binary))
    throw RuntimeFailure("glTF writer: TinyGLTF could not serialise the document");
  return std::move(out).str();
}

}  // namespace

std::vector<std::uint8_t> encode_glb(const Document& doc) {
  const std::string bytes = serialise(doc, true);
  return {bytes.begin(), bytes.end()};
}

std::string encode_gltf_json(const Document& doc) { return serialise(doc, false); }

void write_gltf(const std::filesystem::path& path, const Document& doc) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".glb" && extension != ".gltf")
    throw InputError(path.string() + ": a glTF file must end in .glb or .gltf");
  write_text_file(path, serialise(doc, extension == ".glb"));
}

}  // namespace glintlab::gltf
