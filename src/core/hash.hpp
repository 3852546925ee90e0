#pragma once
// 64-bit FNV-1a, used for cache keys (reference cache, table cache) and table checksums.
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>

namespace glintlab {

class Hasher {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      state_ ^= p[i];
      state_ *= 0x100000001b3ull;
    }
  }
  void text(std::string_view s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  void value(const T& v) {
    bytes(&v, sizeof(T));
  }
  template <typename T>
  void span(std::span<const T> s) {
    value(s.size());
    bytes(s.data(), s.size_bytes());
  }
  [[nodiscard]] std::uint64_t digest() const { return state_; }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ull;
};

}  // namespace glintlab
