#pragma once
/// \file fnv1a.hpp
/// 64-bit FNV-1a: a tiny, stable, platform-independent hash. Used for scenario
/// fingerprints and checkpoint checksums (detects corruption, not an attacker).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fsi::io {

inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

/// Continues the hash `h` over `size` bytes at `data`.
inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = kFnvOffsetBasis) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= bytes[i];
    h *= kFnvPrime;
  }
  return h;
}

inline std::uint64_t fnv1a(std::string_view text) { return fnv1a(text.data(), text.size()); }

}  // namespace fsi::io
