#pragma once
// The frame every cache entry is stored in (docs/bad-input.md, "Caches"): a magic, a line that
// says what the entry was built from, the payload's size and checksum, then the payload. An entry
// is used only if every part matches; anything else (truncated, damaged, foreign, built from
// other inputs, not a regular file) is reported by `problem` and rebuilt by its owner. Entries are
// written atomically, and never over something that is not a regular file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace glintlab {

struct CacheEntryRead {
  std::optional<std::string> payload;  ///< set when the entry is there and sound
  std::string problem;                 ///< why an entry that is there is not used; empty if none
};

/// `magic` is 8 bytes naming the format and its version; `built_from` one line (no '\n').
[[nodiscard]] CacheEntryRead read_cache_entry(const std::filesystem::path& path, std::string_view magic,
                                              std::string_view built_from, std::uintmax_t max_bytes);
/// Returns what went wrong, or an empty string when stored. Never throws: a cache that cannot be
/// written costs a rebuild next time, nothing else.
[[nodiscard]] std::string write_cache_entry(const std::filesystem::path& path, std::string_view magic,
                                            std::string_view built_from, std::string_view payload);

/// "glintlab: warning: ignoring the cache entry PATH (PROBLEM); rebuilding it" on stderr.
void warn_rebuilding_cache_entry(const std::filesystem::path& path, const std::string& problem);

}  // namespace glintlab
