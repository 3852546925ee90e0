#pragma once
// Where glintlab keeps what it can recompute (reference frames, precomputed tables):
// $GLINTLAB_CACHE_DIR, else $XDG_CACHE_HOME/glintlab, else ~/.cache/glintlab; empty if none is set.
// Precomputed tables may live apart ($GLINTLAB_TABLE_CACHE_DIR), so that runs with caches of their
// own (the CLI tests) share tables that take seconds to generate. Read only at the top (Session,
// the CLI) and handed down.
#include <cstdlib>
#include <filesystem>

namespace glintlab {

inline std::filesystem::path default_cache_directory() {
  if (const char* d = std::getenv("GLINTLAB_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "glintlab";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "glintlab";
  return {};
}

inline std::filesystem::path default_table_cache_directory() {
  if (const char* d = std::getenv("GLINTLAB_TABLE_CACHE_DIR"); d && *d) return d;
  return default_cache_directory();
}

}  // namespace glintlab
