// Rule checks shared by the JSON reader and validate(): one wording for every message.
#include "io/scenario_rules.hpp"

#include <cmath>

#include "fsi/error.hpp"
#include "io/number_text.hpp"

namespace fsi::io {

bool Real::contains(double value) const {
  // Written so that NaN fails every comparison and is rejected.
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return std::isfinite(value) && above && below;
}

std::string Real::text() const {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "(" + std::string.
  std::string t = lo_open ? "(" : "[";
  t.append(number_text(lo)).append(", ").append(number_text(hi)).append(hi_open ? ")" : "]");
  if (unit != nullptr && *unit != '\0') t.append(" ").append(unit);
  return t;
}

bool Name::valid_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == '+' || c == '=' || c == '-';
}

std::string Choice::text() const {
  std::string t = "one of";
  for (std::size_t i = 0; i < names.size(); ++i) {
    t.append(i == 0 ? " \"" : ", \"").append(names[i]).append("\"");
  }
  return t;
}

KeyPath KeyPath::operator/(std::string_view key) const {
  return KeyPath{origin, path + "/" + std::string(key)};
}

KeyPath KeyPath::operator/(std::size_t index) const {
  return KeyPath{origin, path + "/" + std::to_string(index)};
}

void fail(const KeyPath& at, const std::string& why) { throw InputError(*at.origin, at.path, why); }

std::string allowed(const Real& rule) { return "must be a finite number in " + rule.text(); }

std::string allowed(const Int& rule) {
  return "must be an integer in [" + std::to_string(rule.lo) + ", " + std::to_string(rule.hi) + "]";
}

std::string allowed(const Name&) {
  return "must be 1 to " + std::to_string(Name::kMaxLength) +
         " characters from A-Z a-z 0-9 _ . + = -";
}

std::string allowed(const Choice& rule) { return "must be " + rule.text(); }

void check(const KeyPath& at, double value, const Real& rule) {
  if (!rule.contains(value)) fail(at, allowed(rule) + ", got " + number_text(value));
}

void check(const KeyPath& at, long long value, const Int& rule) {
  if (value < rule.lo || value > rule.hi) {
    fail(at, allowed(rule) + ", got " + std::to_string(value));
  }
}

void check(const KeyPath& at, const std::string& value, const Name& rule) {
  bool ok = !value.empty() && value.size() <= Name::kMaxLength;
  for (char c : value) ok = ok && Name::valid_char(c);
  if (!ok) fail(at, allowed(rule) + ", got " + quoted(value));
}

void check(const KeyPath& at, const std::string& value, const Choice& rule) {
  for (std::string_view name : rule.names) {
    if (value == name) return;
  }
  fail(at, allowed(rule) + ", got " + quoted(value));
}

std::string quoted(const std::string& text) {
  constexpr std::size_t kMaxShown = 60;  // a message line, not a dump of the input
  std::string q = "\"";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '"' || c == '\\') {
      q += '\\';
      q += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      q += "\\x";
      q += kHex[c >> 4];
      q += kHex[c & 15];
    } else {
      q += static_cast<char>(c);
    }
  }
  if (text.size() > kMaxShown) q += "...";
  return q + "\"";
}

}  // namespace fsi::io
