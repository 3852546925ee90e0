#include "scene/scene.hpp"

#include <span>

#include "core/hash.hpp"
#include "scene/light_kind.hpp"

namespace glintlab {

std::uint64_t Scene::content_hash() const {
  Hasher h;
  h.value(film.width);
  h.value(film.height);
  hash_camera(h, camera);
  for (const auto& m : materials) {
    h.value(m.ndf);
    h.value(m.alpha);
    h.value(m.rho);
    h.value(m.glints.has_value());
    if (m.glints) h.value(*m.glints);
    h.value(m.f0);
    h.value(m.diffuse);
    h.value(m.normal_map_tiling);
    h.value(m.normal_map != nullptr);
    if (m.normal_map) {
      h.value(m.normal_map->width);
      h.value(m.normal_map->height);
      h.span(std::span<const glm::vec3>(m.normal_map->normals));
    }
  }
  for (const auto& s : shapes) {
    h.value(s.transform);
    h.value(s.material);
    h.span(std::span<const glm::vec3>(s.mesh->positions));
    h.span(std::span<const glm::vec3>(s.mesh->normals));
    h.span(std::span<const glm::vec4>(s.mesh->tangents));
    h.span(std::span<const glm::vec2>(s.mesh->uvs));
    h.span(std::span<const std::uint32_t>(s.mesh->indices));
  }
  for (const auto& l : lights) {
    h.text(l.kind->id);
    l.kind->hash(h, l);
  }
  return h.digest();
}

}  // namespace glintlab
