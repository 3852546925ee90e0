#include "prefilter/prefiltered_ndf_layout.hpp"

#include <bit>
#include <string>

#include "core/error.hpp"
#include "prefilter/box_prefix_tables.hpp"

namespace glintlab {

namespace {
std::uint32_t bits(double v) { return std::bit_cast<std::uint32_t>(static_cast<float>(v)); }
std::size_t vec4_aligned(std::size_t floats) { return (floats + 3) / 4 * 4; }
void align_to_vec4(std::vector<float>& values) { values.resize(vec4_aligned(values.size()), 0.0f); }
std::uint32_t word(std::size_t v) {
  if (v >= kNoPrefilteredNdf) throw RuntimeFailure("prefiltered NDFs exceed 2^32 words of GPU memory");
  return static_cast<std::uint32_t>(v);
}
}  // namespace

namespace {

/// Appends pyramid p's header, levels, records and values; returns its header's word.
std::uint32_t pack_pyramid(const PrefilteredNdf& pyramid, bool box_prefix_tables, PrefilteredNdfBuffers& out) {
  const PrefilteredNdf* p = &pyramid;
  auto& rec = out.records;
  const std::size_t header = rec.size();
  const std::size_t levels_at = header + kPrefilteredNdfHeaderWords;
  const std::size_t footprints_at = levels_at + p->levels.size() * kPrefilteredNdfLevelWords;
  const std::size_t groups_at = footprints_at + 4 * p->footprints.size();
  // Each region starts on a multiple of 4 floats: with R a multiple of 4, every rank-R row of
  // the factors is then a run of aligned vec4s (the GLSL point query's vector loads).
  align_to_vec4(out.values);
  const std::size_t angular_at = out.values.size();
  const std::size_t rows_at = vec4_aligned(angular_at + p->angular.size());
  const std::size_t tables_at = vec4_aligned(rows_at + p->rows.size());
  rec.insert(rec.end(), {word(p->levels.size()), word(static_cast<std::size_t>(p->grid.resolution)),
                         word(static_cast<std::size_t>(p->settings.block_size)),
                         word(static_cast<std::size_t>(p->rank())), bits(p->grid.extent), word(footprints_at),
                         word(groups_at), word(angular_at), word(rows_at), word(static_cast<std::size_t>(p->width)),
                         word(static_cast<std::size_t>(p->height)),
                         box_prefix_tables ? word(tables_at) : kNoPrefilteredNdf, p->partial ? 1u : 0u,
                         word(static_cast<std::size_t>(p->settings.elements_per_texel)),
                         bits(p->partial ? p->tile_share(glm::dvec2(0.5 * p->width, 0.5 * p->height), p->levels.back().sigma)
                                         : 0.0),
                         0u});
  for (const PrefilterLevel& l : p->levels)
    rec.insert(rec.end(), {word(static_cast<std::size_t>(l.nx)), word(static_cast<std::size_t>(l.ny)),
                           bits(l.spacing.x), bits(l.spacing.y), l.first_footprint, bits(l.sigma), bits(l.origin.x),
                           bits(l.origin.y)});
  for (const FootprintRecord& f : p->footprints) rec.insert(rec.end(), {f.mask_lo, f.mask_hi, f.first_row, f.group});
  rec.insert(rec.end(), p->group_offsets.begin(), p->group_offsets.end());
  out.values.insert(out.values.end(), p->angular.begin(), p->angular.end());
  align_to_vec4(out.values);
  out.values.insert(out.values.end(), p->rows.begin(), p->rows.end());
  if (box_prefix_tables) {
    align_to_vec4(out.values);
    const BoxPrefixTables tables = glintlab::box_prefix_tables(*p);
    out.values.insert(out.values.end(), tables.values.begin(), tables.values.end());
  }
  word(out.values.size());
  word(rec.size());
  return word(header);
}

}  // namespace

PrefilteredNdfBuffers pack_prefiltered_ndfs(std::span<const std::vector<const PrefilteredNdf*>> per_material,
                                            int max_materials, bool box_prefix_tables) {
  PrefilteredNdfBuffers out;
  out.records.assign(static_cast<std::size_t>(max_materials), kNoPrefilteredNdf);
  for (std::size_t m = 0; m < per_material.size() && m < static_cast<std::size_t>(max_materials); ++m) {
    const std::vector<const PrefilteredNdf*>& pyramids = per_material[m];
    if (pyramids.empty()) continue;
    if (pyramids.size() == 1) {
      out.records[m] = pack_pyramid(*pyramids.front(), box_prefix_tables, out);
      continue;
    }
    if (pyramids.size() != 16) throw RuntimeFailure("a material has 1 pyramid or 16 (Wang tiles'), not " + std::to_string(pyramids.size()));
    const std::size_t table = out.records.size();
    out.records[m] = word(table);
    out.records.resize(table + 16);
    for (std::size_t t = 0; t < 16; ++t) out.records[table + t] = pack_pyramid(*pyramids[t], box_prefix_tables, out);
  }
  return out;
}

PrefilteredNdfBuffers pack_prefiltered_ndfs(std::span<const PrefilteredNdf* const> per_material, int max_materials,
                                            bool box_prefix_tables) {
  std::vector<std::vector<const PrefilteredNdf*>> each;
  for (const PrefilteredNdf* p : per_material) each.push_back(p ? std::vector<const PrefilteredNdf*>{p} : std::vector<const PrefilteredNdf*>{});
  return pack_prefiltered_ndfs(std::span<const std::vector<const PrefilteredNdf*>>(each), max_materials, box_prefix_tables);
}

}  // namespace glintlab
