// glTF materials in glintlab's form: the metallic-roughness model (glTF 2.0, appendix B) with
// KHR_materials_ior, _specular, _anisotropy and _emissive_strength; textures with
// KHR_texture_transform, rows stored bottom first (glintlab's v points up).
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <cstdio>
#include <cstring>
#include <map>

#include "scene/gltf/gltf_model.hpp"

namespace glintlab::gltf {

double extension_number(const ImportContext& c, const tinygltf::Value& object, const char* key, double fallback,
                        const std::string& where) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
    c.fail(where + " " + key + " is not a finite number");
  return v.GetNumberAsDouble();
}

namespace {

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name) {
  auto it = extensions.find(name);
  return it == extensions.end() || !it->second.IsObject() ? nullptr : &it->second;
}

/// The largest magnitude of a texture transform's offset, rotation (radians) and scale, and of an
/// anisotropy rotation: past it, uv and its derivatives overflow single precision in the shaders.
constexpr double kMaxTransformValue = 1e6;

std::string value_text(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

glm::vec2 extension_vec2(const ImportContext& c, const tinygltf::Value& object, const char* key, glm::vec2 fallback,
                         const std::string& where) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2) c.fail(where + " " + key + " is not an array of 2 numbers");
  glm::vec2 out;
  for (int i = 0; i < 2; ++i) {
    const tinygltf::Value& x = v.Get(i);
    const std::string at = where + " " + key + "[" + std::to_string(i) + "]";
    if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble())) c.fail(at + " is not a finite number");
    if (std::abs(x.GetNumberAsDouble()) > kMaxTransformValue)
      c.fail(at + " is " + value_text(x.GetNumberAsDouble()) + "; allowed: -1e+06 to 1e+06");
    out[i] = static_cast<float>(x.GetNumberAsDouble());
  }
  return out;
}

/// extension_number within +-kMaxTransformValue.
double bounded_extension_number(const ImportContext& c, const tinygltf::Value& object, const char* key,
                                const std::string& where) {
  const double v = extension_number(c, object, key, 0.0, where);
  if (std::abs(v) > kMaxTransformValue)
    c.fail(where + " " + key + " is " + value_text(v) + "; allowed: -1e+06 to 1e+06");
  return v;
}

/// KHR_texture_transform (uv' = T(offset) R(rotation) S(scale) uv in glTF's uv) in glintlab's uv,
/// where v = 1 - v_glTF: the same map conjugated by the flip F(u, v) = (u, 1 - v).
glm::mat3 texture_transform(ImportContext& c, const tinygltf::ExtensionMap& extensions, int tex_coord,
                            const std::string& where) {
  if (tex_coord != 0) c.warn(where + " reads TEXCOORD_" + std::to_string(tex_coord) + "; glintlab reads TEXCOORD_0");
  const tinygltf::Value* t = extension(extensions, "KHR_texture_transform");
  if (!t) return glm::mat3(1.0f);
  const std::string at = where + " KHR_texture_transform";
  if (t->Has("texCoord")) c.warn(at + " texCoord is ignored; glintlab reads TEXCOORD_0");
  const glm::vec2 offset = extension_vec2(c, *t, "offset", glm::vec2(0.0f), at);
  const auto rotation = static_cast<float>(bounded_extension_number(c, *t, "rotation", at));
  const glm::vec2 scale = extension_vec2(c, *t, "scale", glm::vec2(1.0f), at);
  const float cs = std::cos(rotation), sn = std::sin(rotation);
  // Column-major: the spec's rows (cos, sin, 0), (-sin, cos, 0).
  const glm::mat3 translate(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(offset, 1));
  const glm::mat3 rotate(glm::vec3(cs, -sn, 0), glm::vec3(sn, cs, 0), glm::vec3(0, 0, 1));
  const glm::mat3 scaling(glm::vec3(scale.x, 0, 0), glm::vec3(0, scale.y, 0), glm::vec3(0, 0, 1));
  const glm::mat3 flip(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 1, 1));
  return flip * translate * rotate * scaling * flip;
}

/// Channel `k` of texel (x, y) of a decoded image (8 or 16 bits, 4 channels: gltf_import.cpp's
/// loader), in [0, 1].
float channel(const tinygltf::Image& image, int x, int y, int k) {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 4 +
                        static_cast<std::size_t>(k);
  if (image.bits == 16) {
    std::uint16_t v;
    std::memcpy(&v, &image.image[2 * i], 2);
    return static_cast<float>(v) / 65535.0f;
  }
  return static_cast<float>(image.image[i]) / 255.0f;
}

class Textures {
 public:
  explicit Textures(ImportContext& c) : c_(c) {}

  /// The image a texture reference shows (checked), or -1 for none.
  int image_of(int texture, const std::string& where) {
    if (texture < 0) return -1;
    const auto& textures = c_.model.textures;
    if (static_cast<std::size_t>(texture) >= textures.size())
      c_.fail(where + " refers to texture " + std::to_string(texture) + "; the file has " +
              std::to_string(textures.size()));
    const tinygltf::Texture& t = textures[static_cast<std::size_t>(texture)];
    const int image = t.source;
    for (const auto& [name, value] : t.extensions)
      c_.warn("texture " + std::to_string(texture) + "'s extension " + name +
              " is not implemented; its fallback image is used");
    if (image < 0 || static_cast<std::size_t>(image) >= c_.model.images.size())
      c_.fail(where + ": texture " + std::to_string(texture) + " has no image glintlab can read (source " +
              std::to_string(image) + "); allowed: PNG, JPEG, TGA or BMP images");
    if (t.sampler < -1 || (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) >= c_.model.samplers.size()))
      c_.fail(where + ": texture " + std::to_string(texture) + " refers to sampler " + std::to_string(t.sampler) +
              "; the file has " + std::to_string(c_.model.samplers.size()) + " (allowed: one of them, or none)");
    if (t.sampler >= 0) {
      const tinygltf::Sampler& s = c_.model.samplers[static_cast<std::size_t>(t.sampler)];
      if ((s.wrapS != -1 && s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT) ||
          (s.wrapT != -1 && s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT))
        c_.warn("sampler " + std::to_string(t.sampler) + " asks for clamped or mirrored wrapping; glintlab repeats");
    }
    const tinygltf::Image& img = c_.model.images[static_cast<std::size_t>(image)];
    if (img.image.empty() || img.component != 4 || (img.bits != 8 && img.bits != 16)) {
      const bool ktx2 = img.mimeType == "image/ktx2" || img.uri.ends_with(".ktx2") || img.uri.starts_with("data:image/ktx2");
      c_.fail(where + ": image " + std::to_string(image) +
              (ktx2 ? " is a KTX2 texture (KHR_texture_basisu, which glintlab does not implement)"
                    : " (" + (img.mimeType.empty() ? std::string("no mimeType") : img.mimeType) + ") was not decoded") +
              "; allowed: PNG, JPEG, TGA or BMP");
    }
    return image;
  }

  TextureSlot slot(const tinygltf::TextureInfo& info, bool srgb, const std::string& where) {
    TextureSlot s;
    const int image = image_of(info.index, where);
    if (image < 0) return s;
    s.transform = texture_transform(c_, info.extensions, info.texCoord, where);
    auto& cached = cache_[{image, srgb}];
    if (!cached) {
      const tinygltf::Image& img = c_.model.images[static_cast<std::size_t>(image)];
      auto t = std::make_shared<MaterialTexture>();
      t->width = img.width;
      t->height = img.height;
      t->srgb = srgb;
      t->description = c_.file + " image " + std::to_string(image) + (img.name.empty() ? "" : " '" + img.name + "'");
      t->rgba.resize(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 4);
      for (int y = 0; y < img.height; ++y)  // bottom row first
        for (int x = 0; x < img.width; ++x)
          for (int k = 0; k < 4; ++k)
            t->rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4 +
                    static_cast<std::size_t>(k)] =
                static_cast<std::uint8_t>(std::lround(255.0f * channel(img, x, img.height - 1 - y, k)));
      cached = std::move(t);
    }
    s.texture = cached;
    return s;
  }

  /// glTF 2.0, 3.9.3: n = normalize((2 c - 1) * (scale, scale, 1)), +Y up in the image, which is
  /// glintlab's +v; rows stored bottom first.
  std::shared_ptr<const NormalMap> normal_map(const tinygltf::NormalTextureInfo& info, const std::string& where) {
    const int image = image_of(info.index, where);
    if (image < 0) return nullptr;
    if (!std::isfinite(info.scale)) c_.fail(where + " scale is not a finite number");
    const tinygltf::Image& img = c_.model.images[static_cast<std::size_t>(image)];
    auto map = std::make_shared<NormalMap>();
    map->width = img.width;
    map->height = img.height;
    map->description = c_.file + " image " + std::to_string(image) + " (normal texture, scale " +
                       std::to_string(info.scale) + ")";
    map->normals.reserve(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
    const auto scale = static_cast<float>(info.scale);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const int row = img.height - 1 - y;
        glm::vec3 n(2.0f * channel(img, x, row, 0) - 1.0f, 2.0f * channel(img, x, row, 1) - 1.0f,
                    2.0f * channel(img, x, row, 2) - 1.0f);
        n = glm::vec3(scale * n.x, scale * n.y, std::max(n.z, 1e-3f));  // never below the surface
        map->normals.push_back(glm::normalize(n));
      }
    return map;
  }

 private:
  ImportContext& c_;
  std::map<std::pair<int, bool>, std::shared_ptr<const MaterialTexture>> cache_;
};

float unit_factor(const ImportContext& c, double value, const std::string& where) {
  if (!std::isfinite(value) || value < 0.0 || value > 1.0)
    c.fail(where + " has value " + std::to_string(value) + "; allowed: 0 to 1");
  return static_cast<float>(value);
}

Material import_material(ImportContext& c, Textures& textures, const tinygltf::Material& g, int index) {
  const std::string where = "material " + std::to_string(index) + (g.name.empty() ? "" : " '" + g.name + "'");
  Material m;
  m.name = g.name.empty() ? "material" + std::to_string(index) : g.name;
  const auto& pbr = g.pbrMetallicRoughness;
  glm::vec4 base(1.0f);
  if (!pbr.baseColorFactor.empty()) {
    if (pbr.baseColorFactor.size() != 4) c.fail(where + " baseColorFactor does not have 4 numbers");
    for (int i = 0; i < 4; ++i)
      base[i] = unit_factor(c, pbr.baseColorFactor[static_cast<std::size_t>(i)], where + " baseColorFactor");
  }
  const float metallic = unit_factor(c, pbr.metallicFactor, where + " metallicFactor");
  const float roughness = unit_factor(c, pbr.roughnessFactor, where + " roughnessFactor");

  // The non-metal part's f0: ((ior - 1) / (ior + 1))^2, tinted and scaled by KHR_materials_specular.
  double ior = 1.5;
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_ior")) {
    ior = extension_number(c, *e, "ior", 1.5, where + " KHR_materials_ior");
    if (ior != 0.0 && (ior < 1.0 || ior > 10.0))
      c.fail(where + " KHR_materials_ior ior has value " + std::to_string(ior) + "; allowed: 1 to 10 (or 0)");
  }
  const float f0_ior = ior == 0.0 ? 1.0f : static_cast<float>(std::pow((ior - 1.0) / (ior + 1.0), 2.0));
  glm::vec3 dielectric_f0(f0_ior);
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_specular")) {
    const std::string at = where + " KHR_materials_specular";
    const auto factor = unit_factor(c, extension_number(c, *e, "specularFactor", 1.0, at), at + " specularFactor");
    glm::vec3 colour(1.0f);
    if (e->Has("specularColorFactor")) {
      const tinygltf::Value& v = e->Get("specularColorFactor");
      if (!v.IsArray() || v.ArrayLen() != 3) c.fail(at + " specularColorFactor is not an array of 3 numbers");
      for (int i = 0; i < 3; ++i) {
        const double x = v.Get(i).IsNumber() ? v.Get(i).GetNumberAsDouble() : -1.0;
        if (!std::isfinite(x) || x < 0.0 || x > 1e3)
          c.fail(at + " specularColorFactor[" + std::to_string(i) + "] is not a number in 0 to 1000");
        colour[i] = static_cast<float>(x);
      }
    }
    if (e->Has("specularTexture") || e->Has("specularColorTexture"))
      c.warn(where + ": KHR_materials_specular's textures are not implemented; their factors are used");
    dielectric_f0 = glm::min(dielectric_f0 * colour, glm::vec3(1.0f)) * factor;
  }

  // KHR_materials_anisotropy: alpha_x = mix(alpha, 1, strength^2) along the tangent turned by
  // `rotation` towards the bitangent.
  float anisotropy = 0.0f;
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_anisotropy")) {
    const std::string at = where + " KHR_materials_anisotropy";
    anisotropy = unit_factor(c, extension_number(c, *e, "anisotropyStrength", 0.0, at), at + " anisotropyStrength");
    m.anisotropy_rotation = static_cast<float>(bounded_extension_number(c, *e, "anisotropyRotation", at));
    if (e->Has("anisotropyTexture"))
      c.warn(where + ": KHR_materials_anisotropy's anisotropyTexture is not implemented; its factors are used");
  }

  glm::vec3 emissive(0.0f);
  if (!g.emissiveFactor.empty()) {
    if (g.emissiveFactor.size() != 3) c.fail(where + " emissiveFactor does not have 3 numbers");
    for (int i = 0; i < 3; ++i)
      emissive[i] = unit_factor(c, g.emissiveFactor[static_cast<std::size_t>(i)], where + " emissiveFactor");
  }
  if (const tinygltf::Value* e = extension(g.extensions, "KHR_materials_emissive_strength")) {
    const double strength = extension_number(c, *e, "emissiveStrength", 1.0, where + " KHR_materials_emissive_strength");
    if (strength < 0.0 || strength > 1e6)
      c.fail(where + " KHR_materials_emissive_strength emissiveStrength has value " + std::to_string(strength) +
             "; allowed: 0 to 1e6");
    emissive *= static_cast<float>(strength);
  }

  if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty())
    c.warn(where + " has alphaMode " + g.alphaMode + "; glintlab renders every surface opaque");
  if (g.occlusionTexture.index >= 0)
    c.warn("occlusion textures are ignored (glintlab renders direct light, which they do not affect)");

  const float alpha = roughness * roughness;
  m.ndf = Ndf::GGX;
  m.alpha = glm::vec2(glm::mix(alpha, 1.0f, anisotropy * anisotropy), alpha);
  m.f0 = glm::mix(dielectric_f0, glm::vec3(base), metallic);
  m.diffuse = glm::vec3(base) * (1.0f - metallic);
  m.emission = emissive;

  const bool textured = pbr.baseColorTexture.index >= 0 || pbr.metallicRoughnessTexture.index >= 0 ||
                        g.emissiveTexture.index >= 0;
  if (textured) {
    TexturedMetalRough t;
    t.base_color = base;
    t.metallic = metallic;
    t.roughness = roughness;
    t.anisotropy = anisotropy;
    t.dielectric_f0 = dielectric_f0;
    t.base_color_texture = textures.slot(pbr.baseColorTexture, true, where + " baseColorTexture");
    t.metallic_roughness_texture = textures.slot(pbr.metallicRoughnessTexture, false, where + " metallicRoughnessTexture");
    t.emissive_texture = textures.slot(g.emissiveTexture, true, where + " emissiveTexture");
    m.textures = std::move(t);
  }
  if (g.normalTexture.index >= 0) {
    m.normal_map = textures.normal_map(g.normalTexture, where + " normalTexture");
    m.normal_map_transform = texture_transform(c, g.normalTexture.extensions, g.normalTexture.texCoord,
                                               where + " normalTexture");
  }
  return m;
}

}  // namespace

std::vector<Material> import_materials(ImportContext& c) {
  Textures textures(c);
  std::vector<Material> out;
  for (std::size_t i = 0; i < c.model.materials.size(); ++i)
    out.push_back(import_material(c, textures, c.model.materials[i], static_cast<int>(i)));
  return out;
}

}  // namespace glintlab::gltf
