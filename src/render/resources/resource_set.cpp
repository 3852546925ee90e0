#include "render/resources/resource_set.hpp"

#include "tables/registry.hpp"

namespace glintlab {

namespace {
constexpr std::string_view kTablePrefix = "table:";

bool is_table(const std::string& id) { return id.starts_with(kTablePrefix); }
std::string table_of(const std::string& id) { return id.substr(kTablePrefix.size()); }
}  // namespace

void ResourceSet::require(std::span<const std::string> ids, const ResourceContext& context) {
  for (const std::string& id : ids) {
    if (is_table(id)) {
      tables_.require(std::vector<std::string>{table_of(id)});
      continue;
    }
    const ResourceType& type = find_resource_type(id);
    const std::string key = id + "|" + type.key(context);
    if (!resident_.contains(key)) resident_.emplace(key, type.make(context));
  }
}

void ResourceSet::bind(std::span<const std::string> ids, const ResourceContext& context) {
  require(ids, context);
  for (const std::string& id : ids) {
    if (is_table(id)) {
      const Table& table = find_table(table_of(id));
      glBindTextureUnit(static_cast<GLuint>(table.unit), tables_.texture(table.source.id));
      continue;
    }
    find(id, context)->bind();
  }
}

const GpuResource* ResourceSet::find(const std::string& id, const ResourceContext& context) const {
  const auto it = resident_.find(id + "|" + find_resource_type(id).key(context));
  return it == resident_.end() ? nullptr : it->second.get();
}

}  // namespace glintlab
