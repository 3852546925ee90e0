#pragma once
// The resources resident for one scene (render/resources/resource.hpp): each made on its first
// request for a given key and kept while the scene lives; the tables among them through GpuTables,
// which also reports how each was built (`glintlab info`).
#include <map>
#include <memory>
#include <span>
#include <string>

#include "render/resources/resource.hpp"
#include "tables/gpu_tables.hpp"

namespace glintlab {

class ResourceSet {
 public:
  explicit ResourceSet(TableCache cache) : tables_(std::move(cache)) {}

  /// Makes each of `ids` resident for `context` (a current GL context is needed).
  void require(std::span<const std::string> ids, const ResourceContext& context);
  /// require(), then binds each of `ids` (as made for `context`).
  void bind(std::span<const std::string> ids, const ResourceContext& context);
  /// A resident resource, or null.
  [[nodiscard]] const GpuResource* find(const std::string& id, const ResourceContext& context) const;

  [[nodiscard]] const GpuTables& tables() const { return tables_; }
  [[nodiscard]] const TableCache& cache() const { return tables_.cache(); }

 private:
  GpuTables tables_;
  std::map<std::string, std::unique_ptr<GpuResource>> resident_;  ///< by "id|key"
};

}  // namespace glintlab
