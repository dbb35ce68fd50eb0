#pragma once
/// \file scenario_rules.hpp
/// Checking one value against its rule from scenario_schema.hpp, and the uniform
/// InputError text for it: `<file>: <key path>: must be ..., got ...`.
#include <string>

#include "io/scenario_schema.hpp"

namespace fsi::io {

/// Where a value sits: the file (or "<string>") and the JSON pointer of the key.
struct KeyPath {
  const std::string* origin;
  std::string path;
  /// The path of a member or array item below this one.
  KeyPath operator/(std::string_view key) const;
  KeyPath operator/(std::size_t index) const;
};

/// Throws fsi::InputError(origin, path, why).
[[noreturn]] void fail(const KeyPath& at, const std::string& why);

/// "must be a finite number in (0, 1] s" (the allowed part of a message).
std::string allowed(const Real& rule);
std::string allowed(const Int& rule);
std::string allowed(const Name& rule);
std::string allowed(const Choice& rule);

void check(const KeyPath& at, double value, const Real& rule);
void check(const KeyPath& at, long long value, const Int& rule);
void check(const KeyPath& at, const std::string& value, const Name& rule);
void check(const KeyPath& at, const std::string& value, const Choice& rule);

/// `text` with quotes, control characters escaped and long text cut (for messages).
std::string quoted(const std::string& text);

}  // namespace fsi::io
