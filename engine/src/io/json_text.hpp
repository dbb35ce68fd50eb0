#pragma once
/// \file json_text.hpp
/// Bounded JSON input: reading a small text file and parsing it with limits on size and
/// nesting depth, rejecting duplicate keys, and turning every parser failure into an
/// fsi::InputError with line/column or the key path where parsing stopped.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace fsi::io {

/// Largest scenario text accepted; a real scenario is a few kB.
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{1} << 20;
/// Deepest nesting accepted; the scenario format needs 5 levels.
inline constexpr int kMaxJsonDepth = 32;

/// The whole file as text; throws InputError(file, "", why) if it is missing, not a
/// regular file, unreadable or larger than `max_bytes` (checked before reading).
std::string read_text_file(const std::filesystem::path& file, std::size_t max_bytes);

/// Explains what a JSON value at a key path should have been; used to word the error
/// for numbers that overflow a double, which the parser rejects before we see them.
using AllowedAt = std::function<std::string(const std::string& key_path)>;

/// Parses `text` (at most kMaxScenarioBytes, depth at most kMaxJsonDepth, no duplicate
/// keys). Throws InputError(origin, key path or "", why).
nlohmann::json parse_json_text(const std::string& text, const std::string& origin,
                               const AllowedAt& allowed_at);

}  // namespace fsi::io
