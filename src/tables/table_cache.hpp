#pragma once
// Precomputed tables on disk: generated once, stored atomically under a key of the table's id,
// generator version and settings, and read back on later runs. An entry that does not match what
// is asked for, is truncated or fails its checksum is regenerated, never trusted. The cache never
// prints: progress and warnings go to the TableObserver its owner gives it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tables/table_source.hpp"

namespace glintlab {

/// Where table building reports to; the top layer decides how (a progress bar, stderr). Optional.
struct TableObserver {
  std::function<void(const TableSource&, int done, int total)> progress;
  std::function<void(const TableSource&, const std::string& message)> warning;
};

/// How a table's values came to be in memory.
struct TableBuild {
  bool generated = false;          ///< true: generated now; false: loaded from the cache
  double milliseconds = 0.0;       ///< spent generating (and storing) or loading
  double generation_ms = 0.0;      ///< what generating took, now or when the entry was written
};

struct BuiltTable {
  std::vector<float> values;
  TableBuild build;
};

/// The cache key: a hash of the id, the generator version and the settings.
[[nodiscard]] std::uint64_t table_key(const TableSource& source);

class TableCache {
 public:
  /// An empty directory disables the cache: every table is generated and nothing is written.
  explicit TableCache(std::filesystem::path directory, TableObserver observer = {});

  [[nodiscard]] const std::filesystem::path& directory() const { return directory_; }
  [[nodiscard]] const TableObserver& observer() const { return observer_; }
  /// <directory>/<id>-<key as 16 hex digits>.table
  [[nodiscard]] std::filesystem::path path(const TableSource& source) const;

  /// The cached values if an intact entry for exactly this table is there; otherwise generated
  /// values, then stored (a failure to store is a warning: the cache is an optimisation).
  [[nodiscard]] BuiltTable load_or_generate(const TableSource& source) const;
  /// Whether an entry is there (its header matches this table and its size is right; the values
  /// are not read), with the generation time it records. For listings that must not generate.
  [[nodiscard]] std::optional<double> cached_generation_ms(const TableSource& source) const;

 private:
  [[nodiscard]] std::optional<BuiltTable> load(const TableSource& source) const;
  void store(const TableSource& source, const BuiltTable& table) const;

  std::filesystem::path directory_;
  TableObserver observer_;
};

}  // namespace glintlab
