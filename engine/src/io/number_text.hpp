#pragma once
/// \file number_text.hpp
/// Doubles as text that reads back bit-identically (shortest round-trip form), for
/// messages, CSV and VTK files. Locale-independent, unlike printf("%g").
#include <charconv>
#include <string>

namespace fsi::io {

/// Shortest decimal text that parses back to exactly `value` ("inf", "nan" if not finite).
inline std::string number_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace fsi::io
