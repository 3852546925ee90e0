#pragma once
// 64-bit FNV-1a, used for cache keys (reference cache, table cache) and table checksums.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
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
  /// The digest as 16 lower-case hex digits (keys and file names).
  [[nodiscard]] std::string hex() const {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(i)] = kDigits[(state_ >> (60 - 4 * i)) & 0xf];
    return out;
  }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ull;
};

}  // namespace glintlab
