#include "tables/table_cache.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/file_access.hpp"
#include "core/hash.hpp"

namespace glintlab {
namespace {

// An entry: this header, the id, the settings, then value_count floats (native byte order: the
// cache belongs to one machine).
struct EntryHeader {
  char magic[8] = {'G', 'L', 'T', 'A', 'B', 'L', 'E', '1'};
  std::uint32_t version = 0;
  std::uint32_t id_size = 0;
  std::uint32_t settings_size = 0;
  std::uint32_t reserved = 0;
  std::uint64_t value_count = 0;
  std::uint64_t checksum = 0;  ///< FNV-1a of the values' bytes: catches damage a size check cannot
  double generation_ms = 0.0;
};
constexpr EntryHeader kExpectedMagic{};

std::uint64_t checksum(const std::vector<float>& values) {
  Hasher h;
  h.bytes(values.data(), values.size() * sizeof(float));
  return h.digest();
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// The header of `path` if it describes exactly `source` and the file has exactly its size.
std::optional<EntryHeader> read_matching_header(const std::filesystem::path& path, const TableSource& source,
                                                std::ifstream& in) {
  EntryHeader h;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || !in.read(reinterpret_cast<char*>(&h), sizeof h)) return std::nullopt;
  if (std::memcmp(h.magic, kExpectedMagic.magic, sizeof h.magic) != 0 || h.version != source.version ||
      h.id_size != source.id.size() || h.settings_size != source.settings.size() ||
      h.value_count != source.value_count ||
      size != sizeof h + h.id_size + h.settings_size + h.value_count * sizeof(float))
    return std::nullopt;
  std::string id(h.id_size, '\0'), settings(h.settings_size, '\0');
  if (!in.read(id.data(), static_cast<std::streamsize>(id.size())) ||
      !in.read(settings.data(), static_cast<std::streamsize>(settings.size())) || id != source.id ||
      settings != source.settings)
    return std::nullopt;
  return h;
}

}  // namespace

std::uint64_t table_key(const TableSource& source) {
  Hasher h;
  h.text("glintlab-table");
  h.text(source.id);
  h.value(source.version);
  h.text(source.settings);
  return h.digest();
}

TableCache::TableCache(std::filesystem::path directory, TableObserver observer)
    : directory_(std::move(directory)), observer_(std::move(observer)) {}

std::filesystem::path TableCache::path(const TableSource& source) const {
  char key[17];
  std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(table_key(source)));
  return directory_ / (source.id + "-" + key + ".table");
}

std::optional<double> TableCache::cached_generation_ms(const TableSource& source) const {
  if (directory_.empty() || file_kind(path(source), false) != FileKind::regular) return std::nullopt;
  std::ifstream in(path(source), std::ios::binary);
  if (!in) return std::nullopt;
  const auto header = read_matching_header(path(source), source, in);
  return header ? std::optional<double>(header->generation_ms) : std::nullopt;
}

std::optional<BuiltTable> TableCache::load(const TableSource& source) const {
  if (directory_.empty()) return std::nullopt;
  const auto file = path(source);
  // Opened only as a regular file: a FIFO or a device in its place would block or never end.
  if (const FileKind kind = file_kind(file, false); kind != FileKind::regular) {
    if (kind != FileKind::missing && observer_.warning)
      observer_.warning(source, "ignoring the cache entry " + file.string() + " (it is " +
                                    std::string(describe(kind)) + "); generating the table, and not storing it there");
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  BuiltTable table;
  std::string problem;
  if (const auto header = read_matching_header(file, source, in); !header) {
    problem = "its header does not match the table or its size is wrong";
  } else {
    table.values.resize(source.value_count);
    if (!in.read(reinterpret_cast<char*>(table.values.data()),
                 static_cast<std::streamsize>(table.values.size() * sizeof(float))))
      problem = "it is truncated";
    else if (checksum(table.values) != header->checksum)
      problem = "its checksum is wrong";
    else if (source.check)
      problem = source.check(table.values);
    table.build.generation_ms = header->generation_ms;
  }
  if (!problem.empty()) {
    if (observer_.warning)
      observer_.warning(source, "ignoring the cache entry " + file.string() + " (" + problem + "); regenerating");
    return std::nullopt;
  }
  table.build.milliseconds = ms_since(start);
  return table;
}

void TableCache::store(const TableSource& source, const BuiltTable& table) const {
  const auto file = path(source);
  try {
    EntryHeader h;
    h.version = source.version;
    h.id_size = static_cast<std::uint32_t>(source.id.size());
    h.settings_size = static_cast<std::uint32_t>(source.settings.size());
    h.value_count = table.values.size();
    h.checksum = checksum(table.values);
    h.generation_ms = table.build.generation_ms;
    AtomicFile atomic(file);
    {
      std::ofstream out(atomic.temp_path(), std::ios::binary);
      out.write(reinterpret_cast<const char*>(&h), sizeof h);
      out.write(source.id.data(), static_cast<std::streamsize>(source.id.size()));
      out.write(source.settings.data(), static_cast<std::streamsize>(source.settings.size()));
      out.write(reinterpret_cast<const char*>(table.values.data()),
                static_cast<std::streamsize>(table.values.size() * sizeof(float)));
      if (!out) throw std::runtime_error(atomic.temp_path().string() + ": cannot write");
    }
    atomic.commit();
  } catch (const std::exception& e) {
    if (observer_.warning) observer_.warning(source, "cannot store it in the cache: " + std::string(e.what()));
  }
}

BuiltTable TableCache::load_or_generate(const TableSource& source) const {
  if (auto cached = load(source)) return *std::move(cached);
  const auto start = std::chrono::steady_clock::now();
  BuiltTable table;
  table.values = source.generate([&](int done, int total) {
    if (observer_.progress) observer_.progress(source, done, total);
  });
  table.build.generated = true;
  table.build.milliseconds = table.build.generation_ms = ms_since(start);
  if (table.values.size() != source.value_count)
    throw std::logic_error("table '" + source.id + "': generate() returned " + std::to_string(table.values.size()) +
                           " values; it declares " + std::to_string(source.value_count));
  if (const FileKind kind = file_kind(path(source), false);
      !directory_.empty() && (kind == FileKind::missing || kind == FileKind::regular))
    store(source, table);
  return table;
}

}  // namespace glintlab
