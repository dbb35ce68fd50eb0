#pragma once
/// \file scenario_overrides.hpp
/// `--set /numerics/time_step_s=1e-3`: changes of single scenario keys, given as a
/// JSON-pointer-like path and a JSON value, applied before the scenario is validated,
/// so a bad key or value gets the scenario validator's message (file, key, range).
///
/// The path addresses the scenario's full JSON (fsi::to_json: every key spelled out),
/// so keys the file leaves out can be set too, e.g. /mesh/blocks/0/y/0/patches=8.
/// Values are JSON (1e-3, true, [0, 1], "halve_step"); a value that is not JSON is
/// taken as a string, so /numerics/failure_policy=halve_step works without quotes.
///
/// Two keys act beyond their own value: /method=chapter (or fsi) switches the numerics
/// that are still at the old preset's value to the new preset's (the others were set on
/// purpose and stay; give --set /method first, then the numerics to change on top), and
/// the renamed /numerics/time_step_max_s and /numerics/time_step_wall_zone_max_s set
/// time_step_max_doublings and time_step_wall_zone_doublings as a file's old keys do.
#include <fsi/scenario.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsi::app {

struct Override {
  std::string path;      ///< "/numerics/time_step_s"
  nlohmann::json value;  ///< parsed value
};

/// Parses "PATH=VALUE". Throws fsi::InputError("--set", PATH, why) when the path does
/// not start with '/' or the '=' is missing.
Override parse_override(const std::string& path_equals_value);

/// Parses a value: JSON if it is JSON, else the text as a JSON string.
nlohmann::json parse_value(const std::string& text);

/// `base` with every override applied (in order), re-validated. Errors name `origin`
/// (e.g. "scenario.json with --set") and the key. Throws fsi::InputError.
Scenario apply_overrides(const Scenario& base, const std::vector<Override>& overrides,
                         const std::string& origin);

/// load_scenario(file) followed by apply_overrides (no overrides: just load_scenario).
Scenario load_scenario_with_overrides(const std::string& file,
                                      const std::vector<Override>& overrides);

/// Writes `scenario` as JSON that loads again (fsi-movie's run scenario.json, fsi-step's
/// `scenario FILE`). Throws InputError naming the file when it cannot be written.
void write_scenario_file(const Scenario& scenario, const std::string& file);

}  // namespace fsi::app
