#include "scene/scene.hpp"

#include <optional>
#include <span>

#include "core/hash.hpp"
#include "scene/lights/environment_map.hpp"
#include "scene/lights/light_kind.hpp"

namespace glintlab {

namespace {

void hash_texture(Hasher& h, const TextureSlot& slot) {
  h.value(slot.transform);
  h.value(slot.texture != nullptr);
  if (!slot.texture) return;
  h.value(slot.texture->width);
  h.value(slot.texture->height);
  h.value(slot.texture->srgb);
  h.span(std::span<const std::uint8_t>(slot.texture->rgba));
}

void hash_mesh(Hasher& h, const Mesh& mesh) {
  h.span(std::span<const glm::vec3>(mesh.positions));
  h.span(std::span<const glm::vec3>(mesh.normals));
  h.span(std::span<const glm::vec4>(mesh.tangents));
  h.span(std::span<const glm::vec2>(mesh.uvs));
  h.span(std::span<const std::uint32_t>(mesh.indices));
}

/// A light as images see it: its kind, the record its GLSL reads, and the emitter drawn for it
/// (mesh, placement, radiance; none when it is not visible). Both come from the kind's own pack and
/// emitter, so a field the kind reads changes the key exactly when it changes what is rendered.
void hash_light(Hasher& h, const Light& light) {
  h.text(light.kind->id);
  h.value(light.kind->pack(light));
  // An environment's map is seen in full (its resource uploads it), not through its record.
  const bool map = !light.kind->compact && light.environment;
  h.value(map);
  if (map) h.span(std::span<const glm::vec3>(light.environment->radiance.pixels()));
  const std::optional<LightEmitter> emitter =
      light.kind->emitter ? light.kind->emitter(light) : std::optional<LightEmitter>{};
  h.value(emitter.has_value());
  if (!emitter) return;
  hash_mesh(h, emitter->mesh);
  h.value(emitter->transform);
  h.value(emitter->radiance);
  h.value(emitter->two_sided);
}

}  // namespace

std::uint64_t Scene::content_hash() const {
  Hasher h;
  h.value(film.width);
  h.value(film.height);
  hash_camera(h, camera);
  for (const auto& m : materials) {
    h.value(m.ndf);
    h.value(m.alpha);
    h.value(m.rho);
    hash_material_kind(h, m);
    h.value(m.f0);
    h.value(m.diffuse);
    h.value(m.normal_map_tiling);
    h.value(m.normal_map_transform);
    h.value(m.anisotropy_rotation);
    h.value(m.emission);
    h.value(m.textures.has_value());
    if (m.textures) {
      const TexturedMetalRough& t = *m.textures;
      h.value(t.base_color);
      h.value(t.metallic);
      h.value(t.roughness);
      h.value(t.anisotropy);
      h.value(t.dielectric_f0);
      hash_texture(h, t.base_color_texture);
      hash_texture(h, t.metallic_roughness_texture);
      hash_texture(h, t.emissive_texture);
    }
    h.value(m.normal_map != nullptr);
    if (m.normal_map) {
      h.value(m.normal_map->width);
      h.value(m.normal_map->height);
      h.value(m.normal_map->wang.has_value());
      if (const auto& w = m.normal_map->wang) {
        h.value(w->tile_size);
        h.value(w->tiles);
        h.value(w->seed);
      }
      h.span(std::span<const glm::vec3>(m.normal_map->normals));
    }
  }
  for (const auto& s : shapes) {
    h.value(s.transform);
    h.value(s.material);
    hash_mesh(h, *s.mesh);
  }
  for (const Light& l : lights) hash_light(h, l);
  return h.digest();
}

}  // namespace glintlab
