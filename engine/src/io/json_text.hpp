#pragma once
/// \file json_text.hpp
/// Bounded JSON input: parsing with limits on size and nesting depth, rejecting duplicate keys, and turning every parser failure into an
/// fsi::InputError with line/column or the key path where parsing stopped.
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace fsi::io {

/// Largest scenario text accepted; a real scenario is a few kB.
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{1} << 20;
/// Deepest nesting accepted; the scenario format needs 5 levels.
inline constexpr int kMaxJsonDepth = 32;

/// Explains what a JSON value at a key path should have been; used to word the error
/// for numbers that overflow a double, which the parser rejects before we see them.
using AllowedAt = std::function<std::string(const std::string& key_path)>;

/// Parses `text` (at most kMaxScenarioBytes, depth at most kMaxJsonDepth, no duplicate
/// keys). Throws InputError(origin, key path or "", why).
nlohmann::json parse_json_text(const std::string& text, const std::string& origin,
                               const AllowedAt& allowed_at);

}  // namespace fsi::io
