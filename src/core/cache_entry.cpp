#include "core/cache_entry.hpp"

#include <cstring>
#include <fstream>
#include <iostream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/hash.hpp"

namespace glintlab {

namespace {

std::uint64_t checksum(std::string_view bytes) {
  Hasher h;
  h.bytes(bytes.data(), bytes.size());
  return h.digest();
}

template <typename T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

CacheEntryRead read_cache_entry(const std::filesystem::path& path, std::string_view magic,
                                std::string_view built_from, std::uintmax_t max_bytes) {
  const FileKind kind = file_kind(path, false);
  if (kind == FileKind::missing) return {};
  if (kind != FileKind::regular) return {std::nullopt, "it is " + std::string(describe(kind))};
  std::string bytes;
  try {
    bytes = read_regular_file(path, "", max_bytes);
  } catch (const InputError& e) {
    return {std::nullopt, e.what()};
  }
  const std::size_t head = magic.size() + built_from.size() + 1;
  if (bytes.size() < head + 2 * sizeof(std::uint64_t) || bytes.compare(0, magic.size(), magic) != 0)
    return {std::nullopt, "not an entry of this format"};
  if (bytes.compare(magic.size(), built_from.size(), built_from) != 0 || bytes[head - 1] != '\n')
    return {std::nullopt, "built from other inputs"};
  std::uint64_t size = 0, sum = 0;
  std::memcpy(&size, bytes.data() + head, sizeof size);
  std::memcpy(&sum, bytes.data() + head + sizeof size, sizeof sum);
  const std::size_t start = head + 2 * sizeof(std::uint64_t);
  if (size != bytes.size() - start) return {std::nullopt, "its size is wrong (truncated or extended)"};
  const std::string_view payload = std::string_view(bytes).substr(start);
  if (checksum(payload) != sum) return {std::nullopt, "its checksum is wrong"};
  return {std::string(payload), {}};
}

std::string write_cache_entry(const std::filesystem::path& path, std::string_view magic, std::string_view built_from,
                              std::string_view payload) {
  try {
    std::string head(magic);
    head.append(built_from);
    head.push_back('\n');
    append(head, static_cast<std::uint64_t>(payload.size()));
    append(head, checksum(payload));
    std::filesystem::create_directories(path.parent_path());
    AtomicFile file(path);  // refuses a target that is not a regular file
    {
      std::ofstream out(file.temp_path(), std::ios::binary);
      out.write(head.data(), static_cast<std::streamsize>(head.size()));
      out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
      if (!out) return file.temp_path().string() + ": cannot write";
    }
    file.commit();
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

void warn_rebuilding_cache_entry(const std::filesystem::path& path, const std::string& problem) {
  std::cerr << "glintlab: warning: ignoring the cache entry " << path.string() << " (" << problem
            << "); rebuilding it\n";
}

}  // namespace glintlab
