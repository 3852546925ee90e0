// Linked into every test binary. Precomputed tables go to the test binaries' shared table cache
// (GLINTLAB_TABLE_CACHE_DIR, unless the caller chose another place), so that every glintlab a
// test starts loads the tables the ctest fixture `generate_tables` made instead of generating its
// own. When GLINTLAB_CACHE_DIR is set (ctest sets it to the build
// tree), the GL drivers' own shader caches go there too, unless the caller chose another place:
// Mesa's (MESA_SHADER_CACHE_DIR, else ~/.cache/mesa_shader_cache) and NVIDIA's
// (__GL_SHADER_DISK_CACHE_PATH, else ~/.nv or ~/.cache/nvidia). Compiled programs are then shared
// by every test process of a build, and no test writes under $HOME. Runs before main, before any
// GL context exists; glintlab processes started by tests inherit it.
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace {

const bool kTableCacheShared = [] { return setenv("GLINTLAB_TABLE_CACHE_DIR", GLINTLAB_TEST_TABLE_CACHE, 0) == 0; }();

const bool kDriverCachesRouted = [] {
  const char* dir = std::getenv("GLINTLAB_CACHE_DIR");
  if (dir == nullptr || *dir == '\0') return false;
  const std::filesystem::path root(dir);
  std::error_code ignored;
  std::filesystem::create_directories(root / "nvidia", ignored);
  setenv("MESA_SHADER_CACHE_DIR", root.c_str(), 0);  // Mesa adds mesa_shader_cache/
  setenv("__GL_SHADER_DISK_CACHE_PATH", (root / "nvidia").c_str(), 0);
  return true;
}();

}  // namespace
