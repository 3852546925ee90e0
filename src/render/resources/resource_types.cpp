// The resource types: one per precomputed table ("table:<id>", made through GpuTables by
// ResourceSet), then every other type, one file each, listed here.
#include <algorithm>
#include <cstdio>
#include <set>

#include "core/error.hpp"
#include "render/resources/resource.hpp"
#include "scene/lights/light_kind.hpp"
#include "tables/registry.hpp"

namespace glintlab {

ResourceType prefiltered_ndf_resource();
ResourceType environment_map_resource();
ResourceType environment_glint_weights_resource();
ResourceType position_normal_elements_resource();
ResourceType environment_lobes_resource();

std::string table_resource_id(const std::string& table_id) { return "table:" + table_id; }

namespace {

ResourceType table_resource(const Table& table) {
  return {
      .id = table_resource_id(table.source.id),
      .title = table.source.title,
      .binding = "sampler " + table.sampler + " at " + table_define(table.source.id),
      .key =
          [&table](const ResourceContext&) {
            char hex[17];
            std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(table_key(table.source)));
            return std::string(hex);
          },
      .estimate_bytes = [&table](const ResourceContext&) { return static_cast<std::uint64_t>(table.gpu_bytes.with_mips); },
      .make = nullptr,  // made and bound by ResourceSet through GpuTables (its build reports: `glintlab info`)
  };
}

void add_unique(std::vector<std::string>& ids, const std::string& id) {
  if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
}

}  // namespace

const std::vector<ResourceType>& all_resource_types() {
  static const std::vector<ResourceType> types = [] {
    std::vector<ResourceType> list;
    for (const Table& t : all_tables()) list.push_back(table_resource(t));
    list.push_back(prefiltered_ndf_resource());
    list.push_back(environment_map_resource());
    list.push_back(position_normal_elements_resource());
    list.push_back(environment_lobes_resource());
    list.push_back(environment_glint_weights_resource());
    return list;
  }();
  return types;
}

const ResourceType& find_resource_type(const std::string& id) {
  const auto& types = all_resource_types();
  auto it = std::find_if(types.begin(), types.end(), [&](const ResourceType& t) { return t.id == id; });
  if (it != types.end()) return *it;
  std::string known;
  for (const auto& t : types) known += (known.empty() ? "" : ", ") + t.id;
  throw InputError("unknown resource '" + id + "'; allowed: " + known);
}

std::vector<std::string> scene_resources(const Scene& scene) {
  std::vector<std::string> ids;
  for (const Material& m : scene.materials)
    for (const std::string& id : m.kind->resources) add_unique(ids, id);
  for (const Light& l : scene.lights)
    for (const std::string& id : l.kind->resources) add_unique(ids, id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::string> method_resources(const MethodDescriptor& method, const ParamValues& params) {
  std::vector<std::string> ids;
  for (const std::string& table : required_tables(method, params)) add_unique(ids, table_resource_id(table));
  for (const std::string& id : method.resources) add_unique(ids, id);
  return ids;
}

std::uint64_t estimate_resource_bytes(const std::vector<std::string>& ids, const ResourceContext& context) {
  std::uint64_t bytes = 0;
  for (const std::string& id : ids) bytes += find_resource_type(id).estimate_bytes(context);
  return bytes;
}

}  // namespace glintlab
