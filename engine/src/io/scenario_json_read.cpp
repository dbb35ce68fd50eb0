// Scenario from JSON: start from Example 1 and overwrite what the file names.
//
// The reader walks scenario_schema.hpp. It checks JSON types and keys here (unknown
// keys are errors: a typo must not silently leave a default in place); value ranges and
// the consistency of the geometry are validate()'s job, which runs on the result.
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "fsi/error.hpp"
#include "fsi/scenario.hpp"
#include "io/bounded_file.hpp"
#include "io/json_text.hpp"
#include "io/number_text.hpp"
#include "io/scenario_rules.hpp"
#include "io/scenario_schema.hpp"

namespace fsi {
namespace io {
namespace {

using json = nlohmann::json;

/// What a JSON value is, for "got ..." in messages.
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::string:
      return "string " + quoted(value.get<std::string>());
    case json::value_t::number_float:
      return "number " + number_text(value.get<double>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return "number " + value.dump();
    case json::value_t::array:
      return "an array of " + std::to_string(value.size());
    default:
      return value.type_name();
  }
}

void expect(bool ok, const KeyPath& at, const std::string& allowed_text, const json& value) {
  if (!ok) fail(at, allowed_text + ", got " + describe(value));
}

// ---- leaf values -------------------------------------------------------------------

void read(const json& j, const KeyPath& at, double& out, const Real& rule) {
  expect(j.is_number(), at, allowed(rule), j);
  out = j.get<double>();
}

void read(const json& j, const KeyPath& at, int& out, const Int& rule) {
  const std::string why = allowed(rule);
  long long value = 0;
  if (j.is_number_unsigned()) {
    const auto u = j.get<unsigned long long>();
    if (u > static_cast<unsigned long long>(rule.hi)) fail(at, why + ", got " + j.dump());
    value = static_cast<long long>(u);
  } else if (j.is_number_integer()) {
    value = j.get<long long>();
  } else if (j.is_number_float()) {
    // 16.0 or 1e3 are integers written as floats; accept them if they are whole.
    const double d = j.get<double>();
    expect(std::isfinite(d) && std::trunc(d) == d && std::abs(d) < 1e15, at, why, j);
    value = static_cast<long long>(d);
  } else {
    expect(false, at, why, j);
  }
  check(at, value, rule);  // before narrowing to int
  out = static_cast<int>(value);
}

void read(const json& j, const KeyPath& at, bool& out, const Flag&) {
  expect(j.is_boolean(), at, "must be true or false", j);
  out = j.get<bool>();
}

void read(const json& j, const KeyPath& at, std::string& out, const Name& rule) {
  expect(j.is_string(), at, allowed(rule), j);
  out = j.get<std::string>();
}

void read(const json& j, const KeyPath& at, std::string& out, const Choice& rule) {
  expect(j.is_string(), at, allowed(rule), j);
  out = j.get<std::string>();
}

/// An enum stored by name (FailurePolicy, Method): rule.names in the order of the enum.
template <class E>
  requires std::is_enum_v<E>
void read(const json& j, const KeyPath& at, E& out, const Choice& rule) {
  expect(j.is_string(), at, allowed(rule), j);
  const auto name = j.get<std::string>();
  for (std::size_t i = 0; i < rule.names.size(); ++i) {
    if (name == rule.names[i]) {
      out = static_cast<E>(i);
      return;
    }
  }
  check(at, name, rule);  // throws with the list of names
}

void read(const json& j, const KeyPath& at, Point2& out, const Real& rule) {
  expect(j.is_array() && j.size() == 2, at,
         "must be a point [x, y] of finite numbers in " + rule.text(), j);
  read(j[0], at / 0, out.x, rule);
  read(j[1], at / 1, out.y, rule);
}

void read(const json& j, const KeyPath& at, Segment2& out, const Real& rule) {
  expect(j.is_array() && j.size() == 2, at,
         "must be a segment [[x0, y0], [x1, y1]] of finite numbers in " + rule.text(), j);
  read(j[0], at / 0, out.a, rule);
  read(j[1], at / 1, out.b, rule);
}

void read(const json& j, const KeyPath& at, std::array<Point2, 4>& out, const Real& rule) {
  expect(j.is_array() && j.size() == 4, at,
         "must be 4 points [[x, y], ...] (counter-clockwise from the lower left) in " + rule.text(),
         j);
  for (std::size_t i = 0; i < 4; ++i) read(j[i], at / i, out[i], rule);
}

// ---- structs and arrays --------------------------------------------------------------

template <class T>
void read(const json& j, const KeyPath& at, T& out, const Fields&);

/// An optional object: present in the file, its keys over the struct's defaults.
template <class T>
void read(const json& j, const KeyPath& at, std::optional<T>& out, const Fields&) {
  out.emplace();
  read(j, at, *out, Fields{});
}

template <class T, class R>
void read(const json& j, const KeyPath& at, std::vector<T>& out, const List<R>& rule) {
  const std::string count = std::to_string(rule.min) + " to " + std::to_string(rule.max);
  expect(j.is_array(), at, "must be an array of " + count + " entries", j);
  if (j.size() < rule.min || j.size() > rule.max) {
    fail(at, "must have " + count + " entries, got " + std::to_string(j.size()));
  }
  out.assign(j.size(), T{});
  for (std::size_t i = 0; i < j.size(); ++i) read(j[i], at / i, out[i], rule.item);
}

/// Reads the members of one JSON object into a struct through its visit_fields.
class ObjectReader {
 public:
  ObjectReader(const json& object, const KeyPath& at) : object_(object), at_(at) {}

  template <class T, class R>
  void operator()(std::string_view key, T& member, const R& rule) {
    known_.push_back(key);
    const auto it = object_.find(std::string(key));
    if (it != object_.end()) read(*it, at_ / key, member, rule);
  }

  /// Rejects keys no member claimed, and missing keys from `required`.
  void finish(std::span<const std::string_view> required) const {
    for (const auto& item : object_.items()) {
      bool known = false;
      for (std::string_view k : known_) known = known || item.key() == k;
      if (!known) fail(at_ / item.key(), "unknown key; allowed here: " + known_list());
    }
    for (std::string_view k : required) {
      if (!object_.contains(std::string(k))) {
        fail(at_ / k, "missing; required here: " + joined(required));
      }
    }
  }

 private:
  std::string known_list() const { return joined(known_); }
  static std::string joined(std::span<const std::string_view> keys) {
    std::string t;
    for (std::string_view k : keys) t += (t.empty() ? "" : ", ") + std::string(k);
    return t;
  }

  const json& object_;
  const KeyPath& at_;
  std::vector<std::string_view> known_;
};

template <class T>
void read(const json& j, const KeyPath& at, T& out, const Fields&) {
  expect(j.is_object(), at, "must be an object {...}", j);
  ObjectReader reader(j, at);
  visit_fields(reader, out);
  reader.finish(required_keys(&out));
}

// ---- the rule for a key path (for messages the parser forces on us) -------------------

/// Finds the rule of the member at a JSON pointer and words what it allows.
class RuleFinder {
 public:
  explicit RuleFinder(std::vector<std::string> segments) : segments_(std::move(segments)) {}

  template <class T, class R>
  void operator()(std::string_view key, T& member, const R& rule) {
    if (depth_ < segments_.size() && segments_[depth_] == key) {
      ++depth_;
      describe_member(member, rule);
    }
  }

  std::string found = "must be a finite number";

 private:
  template <class T>
  void describe_member(T&, const Real& rule) {
    found = allowed(rule);
  }
  template <class T>
  void describe_member(T&, const Int& rule) {
    found = allowed(rule);
  }
  template <class T>
  void describe_member(T& member, const Fields&) {
    visit_fields(*this, member);
  }
  template <class T>
  void describe_member(std::optional<T>&, const Fields& rule) {
    T item{};
    describe_member(item, rule);
  }
  template <class T, class R>
  void describe_member(std::vector<T>&, const List<R>& rule) {
    ++depth_;  // the item index
    T item{};
    describe_member(item, rule.item);
  }
  template <class T, class R>
  void describe_member(T&, const R&) {}

  std::vector<std::string> segments_;
  std::size_t depth_ = 0;
};

std::string allowed_at(const std::string& path) {
  std::vector<std::string> segments;
  for (std::size_t start = 1; start <= path.size();) {
    const auto end = std::min(path.find('/', start), path.size());
    segments.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  Scenario s;
  RuleFinder finder(std::move(segments));
  visit_fields(finder, s);
  return finder.found;
}

// ---- the preset and renamed keys ------------------------------------------------------

/// The file's "method" (fsi when it has none): the preset its numerics start from.
Method read_method(const json& root, const KeyPath& at) {
  Method method = Method::fsi;
  if (root.is_object() && root.contains("method"))
    read(root["method"], at / "method", method, Choice{kMethodNames});
  return method;
}

/// Replaces /numerics/time_step_max_s and /numerics/time_step_wall_zone_max_s (absolute
/// lengths, the format before the doublings) by their doublings relative to the file's
/// time_step_s: floor(log2(max / time_step_s) + 1e-9), 0 (off) for 0.
void convert_renamed_keys(json& root, const KeyPath& at, double preset_time_step_s) {
  if (!root.is_object() || !root.contains("numerics") || !root["numerics"].is_object()) return;
  json& n = root["numerics"];
  double k = preset_time_step_s;
  if (n.contains("time_step_s") && n["time_step_s"].is_number()) k = n["time_step_s"].get<double>();
  for (const RenamedKey& renamed : kRenamedNumericsKeys) {
    if (!n.contains(renamed.old_key)) continue;
    const KeyPath key = at / "numerics" / renamed.old_key;
    if (n.contains(renamed.new_key))
      fail(key, std::string("replaced by ") + renamed.new_key + "; give only " + renamed.new_key);
    const json& value = n[renamed.old_key];
    const std::string why = std::string("(the old form of ") + renamed.new_key +
                            " = floor(log2(value / time_step_s))) must be 0 (off) or a length in [time_step_s, "
                            "time_step_s x 64] = [" + number_text(k) + ", " + number_text(64.0 * k) + "] s";
    expect(value.is_number(), key, why, value);
    const double max_s = value.get<double>();
    int doublings = 0;
    if (max_s != 0.0) {
      const double d = std::floor(std::log2(max_s / k) + 1e-9);
      expect(std::isfinite(max_s) && k > 0.0 && d >= 0.0 && d <= 6.0, key, why, value);
      doublings = static_cast<int>(d);
    }
    n.erase(renamed.old_key);
    n[renamed.new_key] = doublings;
  }
}

}  // namespace
}  // namespace io

Scenario parse_scenario(const std::string& json_text, const std::string& origin) {
  nlohmann::json root = io::parse_json_text(json_text, origin, io::allowed_at);
  const io::KeyPath at{&origin, ""};
  Scenario scenario = example1_scenario(io::read_method(root, at));
  scenario.source = origin;
  io::convert_renamed_keys(root, at, scenario.numerics.time_step_s);
  // One body or a list of them: the list would silently replace the one.
  if (root.is_object() && root.contains("body") && root.contains("bodies"))
    io::fail(at / "body", "give either body (one body) or bodies (a list), not both");
  io::read(root, at, scenario, io::Fields{});
  validate(scenario);
  return scenario;
}

Scenario load_scenario(const std::filesystem::path& file) {
  return parse_scenario(io::read_bounded_file(file, io::kMaxScenarioBytes, "scenario"), file.string());
}

}  // namespace fsi
