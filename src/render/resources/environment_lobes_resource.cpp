// Resource `environment-lobes` (deng2022 under an environment; docs/methods.md#deng2022): the
// scene's environment map fitted by the requesting method's `environment_lobes` spherical
// Gaussians (src/prefilter/environment_sg_fit.hpp; Deng et al. 2022 sec. 5.4), in the storage
// buffer shaders/glints/normal-map/environment_lobes.glsl reads: the count, then per lobe the
// cone it is shaded as, (axis in map space, sine of the half-angle), (RGB power, 0), and its three
// nested cones' sines and shares of the power (SphericalGaussian::nested_cones), (s0, s1, s2, 0)
// and (p0, p1, p2, 0). No environment or no lobes: a count of 0.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/gpu_contract.hpp"
#include "core/hash.hpp"
#include "prefilter/environment_sg_fit.hpp"
#include "render/resources/scene_environment.hpp"
#include "render/resources/storage_buffers_resource.hpp"

namespace glintlab {

namespace {

int requested_lobes(const ResourceContext& c) {
  const auto it = c.params.find("environment_lobes");
  return it == c.params.end() || !scene_environment(c.scene) ? 0 : static_cast<int>(it->second);
}

}  // namespace

ResourceType environment_lobes_resource() {
  return {
      .id = "environment-lobes",
      .title = "the environment fitted by spherical Gaussian lobes (Deng et al. 2022 sec. 5.4)",
      .binding = "storage buffer ENVIRONMENT_LOBES_BINDING",
      .key =
          [](const ResourceContext& c) {
            const EnvironmentMap* map = scene_environment(c.scene);
            Hasher h;
            h.value(requested_lobes(c));
            if (map && requested_lobes(c) > 0) {
              h.value(map->radiance.width());
              h.span(std::span<const glm::vec3>(map->radiance.pixels()));
            }
            return "lobes=" + std::to_string(requested_lobes(c)) + " map=" + h.hex();
          },
      .estimate_bytes =
          [](const ResourceContext& c) { return static_cast<std::uint64_t>(4 + 16 * requested_lobes(c)) * sizeof(float); },
      .make =
          [](const ResourceContext& c) -> std::unique_ptr<GpuResource> {
            std::vector<float> packed(4, 0.0f);  // the count (as float bits of an int), then padding to a vec4
            const int lobes = requested_lobes(c);
            if (lobes > 0) {
              const EnvironmentMap& map = *scene_environment(c.scene);
              const SphericalGaussianFit fit =
                  fit_spherical_gaussians(map, lobes, std::min(kSphericalGaussianFitRows, map.radiance.height()));
              packed[0] = std::bit_cast<float>(static_cast<std::int32_t>(fit.lobes.size()));
              for (const SphericalGaussian& g : fit.lobes) {
                const glm::dvec3 power = g.integral();
                const auto nested = g.nested_cones();
                packed.insert(packed.end(), {static_cast<float>(g.axis.x), static_cast<float>(g.axis.y),
                                             static_cast<float>(g.axis.z), static_cast<float>(g.cone_half_angle_sine()),
                                             static_cast<float>(power.r), static_cast<float>(power.g),
                                             static_cast<float>(power.b), 0.0f});
                for (const auto& c : nested) packed.push_back(static_cast<float>(c.sine));
                packed.push_back(0.0f);
                for (const auto& c : nested) packed.push_back(static_cast<float>(c.share));
                packed.push_back(0.0f);
              }
            }
            auto resource = std::make_unique<StorageBuffersResource>();
            resource->add(kEnvironmentLobesBinding, packed);
            check_gl("uploading the environment's lobes");
            return resource;
          },
  };
}

}  // namespace glintlab
