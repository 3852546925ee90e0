#pragma once
// The precomputed tables resident on the GPU: each one required is loaded from the TableCache (or
// generated and cached there), uploaded once and then bound at its unit for every draw. GpuScene
// owns one (render/gpu_scene.hpp says which tables it requires).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tables/registry.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {

/// What building one table cost: `glintlab info` formats it.
struct TableReport {
  const Table* table = nullptr;
  TableBuild build;         ///< generated now or loaded from the cache, and how long that took
  double upload_ms = 0.0;   ///< making its texture
};

class GpuTables {
 public:
  explicit GpuTables(TableCache cache);

  /// Makes each table resident that is not yet (ids of all_tables(); throws InputError for an
  /// unknown id). Needs a current GL context.
  void require(std::span<const std::string> ids);
  /// Binds every resident table's texture at its unit (a program samples only those it declares).
  void bind() const;
  /// The texture of a resident table, or 0.
  [[nodiscard]] GLuint texture(const std::string& id) const;
  /// Where tables are cached (also where prefiltered NDF pyramids are: src/render/resources/prefiltered_ndf_resource.cpp).
  [[nodiscard]] const TableCache& cache() const { return cache_; }
  /// One per resident table, in the order they were required.
  [[nodiscard]] std::vector<TableReport> reports() const;

 private:
  struct Resident {
    TableReport report;
    gl::Texture texture;
  };
  TableCache cache_;
  std::vector<Resident> resident_;
};

/// Every registered table built (loaded or generated) and uploaded: what `glintlab info` shows.
/// Needs a current GL context; the textures are released on return.
std::vector<TableReport> build_every_table(const TableCache& cache);

/// What is known of a table without a GL context and without generating it: `glintlab methods`.
struct TableSummary {
  const Table* table = nullptr;
  std::optional<double> cached_generation_ms;  ///< set when the cache holds it: what generating took
};
TableSummary summarise_table(const std::string& id, const TableCache& cache);

}  // namespace glintlab
