#pragma once
// Shared by the fuzz targets (docs/fuzzing.md). The loaders under test read paths, so each input is
// written to a file in this process's own scratch directory; relative references inside an input
// (a glTF buffer, an OBJ mtllib, a scene's mesh file) resolve there.
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace glintlab::fuzz {

// A run that ends by a finding, a timeout or -runs skips atexit: its directory is removed by the
// next run, once its process is gone.
inline void remove_stale_scratch_directories(const std::filesystem::path& temp) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(temp, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("glintlab-fuzz-", 0) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + 14, &end, 10);
    if (pid > 0 && *end == '\0' && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      std::filesystem::remove_all(entry.path(), ec);
  }
}

inline const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path dir = [] {
    remove_stale_scratch_directories(std::filesystem::temp_directory_path());
    auto d = std::filesystem::temp_directory_path() / ("glintlab-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_directory(), ignored);
    });
    return d;
  }();
  return dir;
}

/// Writes the input to scratch_directory()/name (replacing the previous one) and returns the path.
inline std::filesystem::path write_input(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const auto path = scratch_directory() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace glintlab::fuzz
