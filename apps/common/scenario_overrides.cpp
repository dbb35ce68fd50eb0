// Scenario key overrides through the scenario's full JSON and fsi::parse_scenario.
#include "scenario_overrides.hpp"

#include <fsi/error.hpp>
#include <fstream>

namespace fsi::app {

nlohmann::json parse_value(const std::string& text) {
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) return nlohmann::json(text);
  return value;
}

Override parse_override(const std::string& path_equals_value) {
  const std::size_t eq = path_equals_value.find('=');
  if (eq == std::string::npos) {
    throw InputError("--set", path_equals_value,
                     "wants KEY=VALUE, e.g. /numerics/time_step_s=1e-3");
  }
  Override o{path_equals_value.substr(0, eq), parse_value(path_equals_value.substr(eq + 1))};
  if (o.path.empty() || o.path[0] != '/') {
    throw InputError("--set", o.path,
                     "the key must be a path starting with '/', e.g. /solid/mu_pa");
  }
  return o;
}

namespace {

/// The numerics of a method's preset as JSON, or null for a name that is none.
nlohmann::json preset_numerics(const nlohmann::json& name) {
  for (const Method m : {Method::fsi, Method::chapter}) {
    const nlohmann::json s = nlohmann::json::parse(to_json(example1_scenario(m)));
    if (s["method"] == name) return s["numerics"];
  }
  return nullptr;
}

/// --set /method=NAME on a whole scenario: the numerics still at the old preset's values
/// take the new preset's; those set otherwise (by the file or an earlier --set) stay.
void switch_method(nlohmann::json& doc, const nlohmann::json& name) {
  const nlohmann::json from = preset_numerics(doc["method"]), to = preset_numerics(name);
  if (from.is_null() || to.is_null()) return;  // parse_scenario words the error
  for (auto& [key, value] : doc["numerics"].items())
    if (from.contains(key) && to.contains(key) && value == from[key]) value = to[key];
}

}  // namespace

Scenario apply_overrides(const Scenario& base, const std::vector<Override>& overrides,
                         const std::string& origin) {
  if (overrides.empty()) return base;
  nlohmann::json doc = nlohmann::json::parse(to_json(base));
  for (const Override& o : overrides) {
    try {
      const nlohmann::json::json_pointer pointer(o.path);
      // Only existing parents: a typo deeper down is an unknown key for parse_scenario,
      // never a silently created object tree.
      if (!doc.contains(pointer.parent_pointer())) {
        throw InputError(origin, o.path,
                         "no such key (parent " + pointer.parent_pointer().to_string() +
                             " is not in the scenario)");
      }
      // A key renamed in the format (e.g. time_step_max_s): set it in its old form, which
      // parse_scenario converts, instead of the new key the base scenario carries.
      for (const RenamedKey& renamed : kRenamedNumericsKeys)
        if (o.path == std::string("/numerics/") + renamed.old_key) doc["numerics"].erase(renamed.new_key);
      if (o.path == "/method") switch_method(doc, o.value);
      doc[pointer] = o.value;
    } catch (const nlohmann::json::exception& e) {
      throw InputError(origin, o.path, std::string("cannot set this key: ") + e.what());
    }
  }
  Scenario s = parse_scenario(doc.dump(), origin);
  s.source = base.source;
  return s;
}

Scenario load_scenario_with_overrides(const std::string& file,
                                      const std::vector<Override>& overrides) {
  const Scenario base = load_scenario(file);
  return apply_overrides(base, overrides, file + " with --set");
}

void write_scenario_file(const Scenario& scenario, const std::string& file) {
  std::ofstream out(file, std::ios::trunc);
  out << to_json(scenario) << '\n';
  if (!out) throw InputError(file, "", "cannot write the scenario");
}

}  // namespace fsi::app
