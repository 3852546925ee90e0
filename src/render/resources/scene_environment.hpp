#pragma once
// The scene's environment map as the resources made from it see it (environment-map,
// environment-glint-weights, environment-lobes).
#include <span>

#include "core/hash.hpp"
#include "scene/lights/environment_map.hpp"
#include "scene/scene.hpp"

namespace glintlab {

/// The scene's environment map (at most one: the parser checks), or null.
inline const EnvironmentMap* scene_environment(const Scene& scene) {
  for (const Light& l : scene.lights)
    if (l.environment) return l.environment.get();
  return nullptr;
}

/// Adds what a resource made from the map depends on, its size and texels (or its absence), to a
/// resource key.
inline void hash_environment(Hasher& h, const EnvironmentMap* map) {
  h.value(map != nullptr);
  if (!map) return;
  h.value(map->radiance.width());
  h.value(map->radiance.height());
  h.span(std::span<const glm::vec3>(map->radiance.pixels()));
}

}  // namespace glintlab
