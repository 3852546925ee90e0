#pragma once
// Shared by the fuzz targets (docs/fuzzing.md). The loaders under test read paths, so each input is
// written to a file in this process's own scratch directory; relative references inside an input
// (a glTF buffer, an OBJ mtllib, a scene's mesh file) resolve there.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace glintlab::fuzz {

inline const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path dir = [] {
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
