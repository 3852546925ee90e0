#include "core/available_memory.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/error.hpp"

namespace glintlab {

namespace {

std::optional<std::uint64_t> read_number_file(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  std::uint64_t value = 0;
  if (std::from_chars(text.data(), text.data() + text.size(), value).ec != std::errc()) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  std::uint64_t value = 0;
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return value * 1024;  // kB
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> available_memory() {
  if (const char* limit = std::getenv("GLINTLAB_MEMORY_MIB"); limit && *limit) {
    const std::string text = limit;
    std::uint64_t mib = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), mib);
    if (ec != std::errc() || end != text.data() + text.size() || mib == 0 || mib > (1ull << 40))
      throw InputError("GLINTLAB_MEMORY_MIB=" + text + ": allowed: a whole number of MiB, 1 .. 2^40");
    return mib << 20;
  }
  std::optional<std::uint64_t> available = mem_available();
  const auto limit = read_number_file("/sys/fs/cgroup/memory.max");
  const auto usage = read_number_file("/sys/fs/cgroup/memory.current");
  if (limit && usage) {
    const std::uint64_t left = *limit > *usage ? *limit - *usage : 0;
    available = available ? std::min(*available, left) : left;
  }
  return available;
}

std::string format_bytes(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (1ull << 30)) std::snprintf(text, sizeof text, "%.2f GiB", static_cast<double>(bytes) / (1ull << 30));
  else std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1ull << 20));
  return text;
}

}  // namespace glintlab
