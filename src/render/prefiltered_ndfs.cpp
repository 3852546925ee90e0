#include "render/prefiltered_ndfs.hpp"

#include "core/gpu_contract.hpp"
#include "gl/context.hpp"
#include "prefilter/prefilter_cache.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"

namespace glintlab {

PrefilteredNdfs::PrefilteredNdfs(const std::vector<Material>& materials, std::filesystem::path cache_directory)
    : cache_directory_(std::move(cache_directory)) {
  for (const Material& m : materials)
    sources_.push_back(m.is("normal-map-glints") && m.normal_map
                           ? Source{m.normal_map, m.kind_param("intrinsic_roughness")}
                           : Source{});
}

PrefilteredNdfs::Resident& PrefilteredNdfs::resident(const PrefilterSettings& settings) {
  const std::string key = settings.describe();
  if (auto it = resident_.find(key); it != resident_.end()) return it->second;
  Resident r;
  std::vector<const PrefilteredNdf*> pointers;
  for (const Source& s : sources_) {
    r.per_material.push_back(
        s.map ? std::make_unique<PrefilteredNdf>(
                    load_or_precompute_prefiltered_ndf(*s.map, s.intrinsic_roughness, settings, cache_directory_))
              : nullptr);
    pointers.push_back(r.per_material.back().get());
  }
  PrefilteredNdfBuffers packed = pack_prefiltered_ndfs(pointers, kMaxMaterials);
  if (packed.values.empty()) packed.values.push_back(0.0f);  // a buffer is never empty
  r.records = gl::make_buffer(static_cast<GLsizeiptr>(packed.records.size() * sizeof(std::uint32_t)),
                              packed.records.data());
  r.values = gl::make_buffer(static_cast<GLsizeiptr>(packed.values.size() * sizeof(float)), packed.values.data());
  check_gl("uploading prefiltered NDFs");
  return resident_.emplace(key, std::move(r)).first->second;
}

void PrefilteredNdfs::bind(const PrefilterSettings& settings) {
  const Resident& r = resident(settings);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfRecordsBinding, r.records.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfValuesBinding, r.values.id());
}

const PrefilteredNdf* PrefilteredNdfs::pyramid(int material, const PrefilterSettings& settings) {
  return resident(settings).per_material[static_cast<std::size_t>(material)].get();
}

}  // namespace glintlab
