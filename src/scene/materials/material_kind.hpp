#pragma once
// A kind of material (Mitsuba 3's plugins, pbrt-v4's one concept per file): this descriptor, in
// src/scene/materials/<id>.cpp, plus the GLSL file shaders/materials/<id>.glsl with the fixed
// material interface (docs/extending.md, "A material kind"). Each kind registers itself
// (GLINTLAB_REGISTER_MATERIAL_KIND); its registration key orders the kinds and gives their codes.
// From this one declaration come the scene file's keys and their checks, the scene hash, the
// kind's share of the GPU record (MaterialGpu::kind_params) and its GLSL accessors, the program
// variant's define, the dispatch of the material interface (src/render/shader_contract.cpp) and
// the kind's entry in docs/scene-format.md's reference.
#include <string>
#include <string_view>
#include <vector>

#include "core/hash.hpp"

namespace glintlab {

class TomlReader;
struct Material;

/// A scene-file key the kind reads in its own code (parse_lobe) rather than from a declaration, as
/// the reference documents it; its numbers are the constants parse_lobe uses.
struct MaterialKeyDoc {
  std::string key;
  std::string type;          ///< "number", "number or [x, y]", "string"
  std::string default_text;  ///< "0.1", "\"ggx\""
  std::string allowed;       ///< "0.005 .. 0.7", "ggx, beckmann"
  std::string meaning;
};

/// How many floats a kind's own parameters may take: MaterialGpu::kind_params is one vec4.
inline constexpr int kMaxMaterialKindParams = 4;

/// A float parameter of a kind: a scene-file key with its default and range, or a value the kind
/// derives from the others (`derived`), packed in declaration order into MaterialGpu::kind_params.
struct MaterialParamDecl {
  std::string key;  ///< the scene file's key; GLSL reads it as <kind prefix><Key>(MaterialData)
  float default_value = 0.0f;
  double min = 0.0;
  double max = 1.0;
  std::string description;
  bool derived = false;  ///< not a key of the file: set by the kind's `finish` (e.g. from the normal map)
};

struct MaterialKind {
  std::string id;     ///< the scene file's `type`; GLSL: shaders/materials/<id>.glsl
  std::string title;  ///< one line, for listings
  std::string citation;
  std::string summary;  ///< what the kind is, and what methods that do not know it shade (its smooth limit)
  std::vector<MaterialParamDecl> params;
  /// The keys parse_lobe reads (the lobe's roughness and NDF), for the reference.
  std::vector<MaterialKeyDoc> lobe_keys;
  /// Reads the kind's lobe keys (ndf, alpha, sigma, ...) into Material::ndf, alpha and rho, and fails
  /// on lobe keys the kind does not have. Called after `type`, before the kind's params and the
  /// common keys (f0, diffuse, normal_map, ...).
  void (*parse_lobe)(TomlReader& reader, Material& material) = nullptr;
  /// Called once every key is read (the normal map too): derived parameters.
  void (*finish)(TomlReader& reader, Material& material) = nullptr;
  /// The kind's microsurface is the material's normal map: a material without one is refused.
  bool requires_normal_map = false;
  /// The resources the kind's GLSL reads in every method and in the reference
  /// (src/render/resources/resource.hpp; glinty: the glint dictionary, "table:glint-dictionary").
  std::vector<std::string> resources = {};

  /// The kind's code on the GPU: MATERIAL_KIND_<ID> in GLSL, its position in registration order.
  [[nodiscard]] int code() const;
  [[nodiscard]] std::string glsl_file() const { return "materials/" + id + ".glsl"; }
  /// Prefix of the kind's GLSL functions: "binomialGlints" for binomial-glints.
  [[nodiscard]] std::string glsl_prefix() const;
  /// "MATERIAL_KIND_BINOMIAL_GLINTS".
  [[nodiscard]] std::string define() const;
  /// Index of a declared parameter; throws std::logic_error naming the kind for an undeclared one.
  [[nodiscard]] int param_index(std::string_view key) const;
};

/// One registered kind: how to make its descriptor and where it is listed.
struct MaterialKindRegistration {
  MaterialKind (*make)();
  /// Kinds are ordered by ascending key (never by link order); the order is their GPU codes.
  int key;
  const char* source_file;  ///< the descriptor's file, for error messages
};

/// Adds a kind; GLINTLAB_REGISTER_MATERIAL_KIND calls it during static initialisation. Throws
/// std::logic_error once the registry has been read.
bool register_material_kind(const MaterialKindRegistration& registration);

/// Every kind, in the order of their codes. Throws std::logic_error for a repeated id or key or an
/// invalid declaration (an id other than a-z, 0-9 and '-'; more than kMaxMaterialKindParams
/// parameters; a key repeated or not a GLSL identifier; a default outside its range).
const std::vector<MaterialKind>& all_material_kinds();
/// Throws InputError naming the registered kinds when there is none of that id.
const MaterialKind& find_material_kind(const std::string& id);
std::vector<std::string> material_kind_ids();
/// The kind of materials that say no `type` (and of every glTF material): microfacet.
const MaterialKind& default_material_kind();

/// Hashes a material's kind and its parameters (Scene::content_hash).
void hash_material_kind(Hasher& hasher, const Material& material);

}  // namespace glintlab

/// Registers the kind that `make` (a function returning a MaterialKind) builds, ordered by `key`.
/// Write it once, at namespace scope after `make`, in the kind's file.
#define GLINTLAB_REGISTER_MATERIAL_KIND(make, key)                  \
  [[maybe_unused]] static const bool registered_material_##make = \
      ::glintlab::register_material_kind({&make, key, __FILE__})
