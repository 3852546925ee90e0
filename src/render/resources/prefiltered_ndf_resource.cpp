// Resource `prefiltered-ndf` (deng2022; docs/methods.md#deng2022): the CP-compressed NDF pyramid
// of every normal-map-glints material of the scene under the method's precompute settings (a
// map of Wang tiles: one per tile, prefilter/wang_tile_pyramids.hpp)
// (src/prefilter/), read from the disk cache or precomputed, packed into the two storage buffers
// shaders/glints/normal-map/prefiltered_ndf.glsl reads (kPrefilteredNdf*Binding).
#include <cstdio>
#include <string>

#include "core/gpu_contract.hpp"
#include "core/hash.hpp"
#include "prefilter/prefilter_cache.hpp"
#include "prefilter/prefilter_params.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"
#include "prefilter/wang_tile_pyramids.hpp"
#include "render/resources/storage_buffers_resource.hpp"

namespace glintlab {

namespace {

bool has_pyramid(const Material& m) { return m.is("normal-map-glints") && m.normal_map; }


// deng2022's `box_queries` (src/shading/methods/deng2022.cpp): 0, prefix-tables, packs the tables
// of constant-cost box queries; 1, blocks, does without them.
bool wants_box_prefix_tables(const ParamValues& params) {
  const auto it = params.find("box_queries");
  return it == params.end() || it->second == 0.0f;
}

}  // namespace

ResourceType prefiltered_ndf_resource() {
  return {
      .id = "prefiltered-ndf",
      .title = "the normal-map-glints materials' CP-compressed NDF pyramids (Deng et al. 2022)",
      .binding = "storage buffers PREFILTERED_NDF_RECORDS_BINDING, PREFILTERED_NDF_VALUES_BINDING",
      .key =
          [](const ResourceContext& c) {
            // The settings and, per material with a pyramid, what its pyramid is made of.
            Hasher h;
            for (const Material& m : c.scene.materials) {
              h.value(has_pyramid(m));
              if (!has_pyramid(m)) continue;
              const PrefilterSettings settings = prefilter_settings_from(c.params);
              for (int tile = m.normal_map->wang ? 0 : -1; tile < (m.normal_map->wang ? 16 : 0); ++tile)
                h.text(prefiltered_ndf_key(*m.normal_map, m.kind_param("intrinsic_roughness"), settings, tile));
            }
            return prefilter_settings_from(c.params).describe() + " box_prefix_tables=" +
                   std::to_string(wants_box_prefix_tables(c.params)) + " maps=" + h.hex();
          },
      .estimate_bytes =
          [](const ResourceContext& c) {
            std::uint64_t bytes = 4 * kMaxMaterials + sizeof(float);  // each material's word; a value at least
            const PrefilterSettings settings = prefilter_settings_from(c.params);
            for (const Material& m : c.scene.materials)
              if (has_pyramid(m))
                bytes += m.normal_map->wang ? wang_tile_pyramids_bytes_bound(settings, m.normal_map->wang->tile_size,
                                                                             wants_box_prefix_tables(c.params))
                                            : prefiltered_ndf_bytes_bound(settings, m.normal_map->width, m.normal_map->height,
                                                                          wants_box_prefix_tables(c.params));
            return bytes;
          },
      .make =
          [](const ResourceContext& c) -> std::unique_ptr<GpuResource> {
            const PrefilterSettings settings = prefilter_settings_from(c.params);
            // A material's pyramid, or its Wang tiles' 16 (prefilter/wang_tile_pyramids.hpp).
            std::vector<std::vector<PrefilteredNdf>> pyramids;
            std::vector<std::vector<const PrefilteredNdf*>> per_material;
            for (const Material& m : c.scene.materials) {
              pyramids.push_back(has_pyramid(m) ? load_or_precompute_pyramids(*m.normal_map, m.kind_param("intrinsic_roughness"),
                                                                              settings, c.cache.directory())
                                                : std::vector<PrefilteredNdf>{});
              per_material.emplace_back();
              for (const PrefilteredNdf& p : pyramids.back()) per_material.back().push_back(&p);
            }
            const PrefilteredNdfBuffers packed =
                pack_prefiltered_ndfs(per_material, kMaxMaterials, wants_box_prefix_tables(c.params));
            auto resource = std::make_unique<StorageBuffersResource>();
            resource->add(kPrefilteredNdfRecordsBinding, packed.records).add(kPrefilteredNdfValuesBinding, packed.values);
            check_gl("uploading prefiltered NDFs");
            return resource;
          },
  };
}

}  // namespace glintlab
