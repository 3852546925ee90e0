#include "tables/gpu_tables.hpp"

#include <algorithm>
#include <chrono>

#include "gl/context.hpp"

namespace glintlab {

GpuTables::GpuTables(TableCache cache) : cache_(std::move(cache)) {}

void GpuTables::require(std::span<const std::string> ids) {
  for (const std::string& id : ids) {
    if (texture(id) != 0) continue;
    const Table& table = find_table(id);
    Resident r;
    r.report.table = &table;
    const BuiltTable built = cache_.load_or_generate(table.source);
    r.report.build = built.build;
    const auto start = std::chrono::steady_clock::now();
    r.texture = table.upload(built.values);
    glFinish();  // the upload's own time, not the next draw's
    r.report.upload_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    resident_.push_back(std::move(r));
  }
}

void GpuTables::bind() const {
  for (const auto& r : resident_) glBindTextureUnit(static_cast<GLuint>(r.report.table->unit), r.texture.id());
}

GLuint GpuTables::texture(const std::string& id) const {
  const auto it = std::find_if(resident_.begin(), resident_.end(),
                               [&](const Resident& r) { return r.report.table->source.id == id; });
  return it == resident_.end() ? 0 : it->texture.id();
}

std::vector<TableReport> GpuTables::reports() const {
  std::vector<TableReport> out;
  for (const auto& r : resident_) out.push_back(r.report);
  return out;
}

std::vector<TableReport> build_every_table(const TableCache& cache) {
  GpuTables tables(cache);
  for (const auto& t : all_tables()) tables.require(std::vector<std::string>{t.source.id});
  return tables.reports();
}

TableSummary summarise_table(const std::string& id, const TableCache& cache) {
  const Table& table = find_table(id);
  return {&table, cache.cached_generation_ms(table.source)};
}

}  // namespace glintlab
