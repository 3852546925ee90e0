// Resource `position-normal-elements` (yan2016, deng2022's element fallback;
// docs/methods.md#yan2016): every normal-map-glints material's Gaussian elements, p_e and J_e at the
// requesting method's k per texel and axis, computed once from the map
// (src/prefilter/position_normal_elements.hpp) instead of from five texels per element, light and
// pixel; read by shaders/glints/normal-map/position_normal.glsl (POSITION_NORMAL_STORED_ELEMENTS).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "core/gpu_contract.hpp"
#include "core/hash.hpp"
#include "prefilter/position_normal_elements.hpp"
#include "render/resources/storage_buffers_resource.hpp"

namespace glintlab {

namespace {

// A Wang-tiled surface's elements are made from its texels in the shader: no storage per texel of the surface.
bool has_elements(const Material& m) { return m.is("normal-map-glints") && m.normal_map && !m.normal_map->wang; }

// The elements per texel and axis the requesting method sums: deng2022's fallback by its
// `small_footprints` (yan2016: 2, yan2016-k1: 1, clamp: none), else yan2016's `elements_per_texel`
// (choice 0 is k = 1, choice 1 k = 2).
int requested_k(const ParamValues& params) {
  if (const auto it = params.find("small_footprints"); it != params.end())
    return it->second == 0.0f ? 2 : it->second == 1.0f ? 1 : 0;
  const auto it = params.find("elements_per_texel");
  return it == params.end() ? 1 : static_cast<int>(it->second) + 1;
}

}  // namespace

ResourceType position_normal_elements_resource() {
  return {
      .id = "position-normal-elements",
      .title = "the normal-map-glints materials' Gaussian elements (p_e, J_e) of Yan et al. 2016, k per texel",
      .binding = "storage buffers POSITION_NORMAL_ELEMENT_NORMALS_BINDING, POSITION_NORMAL_ELEMENT_JACOBIANS_BINDING",
      .key =
          [](const ResourceContext& c) {
            Hasher h;
            const int k = requested_k(c.params);
            for (const Material& m : c.scene.materials) {
              h.value(k > 0 && has_elements(m));
              if (k > 0 && has_elements(m)) h.span(std::span<const glm::vec3>(m.normal_map->normals));
            }
            return "k=" + std::to_string(k) + " maps=" + h.hex();
          },
      .estimate_bytes =
          [](const ResourceContext& c) {
            std::uint64_t bytes = 4 * (kMaxMaterials + 1) + sizeof(float);
            const int k = requested_k(c.params);
            for (const Material& m : c.scene.materials)
              if (k > 0 && has_elements(m))
                bytes += position_normal_element_bytes(m.normal_map->width, m.normal_map->height, k);
            return bytes;
          },
      .make =
          [](const ResourceContext& c) -> std::unique_ptr<GpuResource> {
            const int k = requested_k(c.params);
            std::vector<std::unique_ptr<PositionNormalDistribution>> distributions;
            std::vector<const PositionNormalDistribution*> per_material;
            for (const Material& m : c.scene.materials) {
              distributions.push_back(nullptr);
              if (k > 0 && has_elements(m)) {
                // The elements do not depend on sigma_r; the distribution only needs one above 0.
                const double sigma_r = std::max(static_cast<double>(m.kind_param("intrinsic_roughness")), 1e-4);
                distributions.back() = std::make_unique<PositionNormalDistribution>(*m.normal_map, sigma_r, k);
              }
              per_material.push_back(distributions.back().get());
            }
            const PositionNormalElementBuffers packed = pack_position_normal_elements(per_material, kMaxMaterials);
            auto resource = std::make_unique<StorageBuffersResource>();
            resource->add(kPositionNormalElementNormalsBinding, packed.normals)
                .add(kPositionNormalElementJacobiansBinding, packed.jacobians);
            check_gl("uploading normal-map elements");
            return resource;
          },
  };
}

}  // namespace glintlab
