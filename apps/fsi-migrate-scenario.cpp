// fsi-migrate-scenario: writes a scenario file of the older format in the current one.
//
//   fsi-migrate-scenario OLD.json [--keep-old-defaults] > NEW.json     (tools/migrate-scenario)
//
// - time_step_max_s and time_step_wall_zone_max_s (absolute lengths) become
//   time_step_max_doublings and time_step_wall_zone_doublings,
//   floor(log2(value / time_step_s)) with the file's time_step_s (0 stays 0, off);
// - --keep-old-defaults adds "method": "chapter" (unless the file names a method), so
//   that the keys the file leaves out keep the values they had before the fsi defaults:
//   the migrated file runs the same numerics as the old one did. Without it those keys
//   take the fsi defaults (docs/scenarios.md).
// Everything else is copied as it stands, layout and all. The result is checked: read
// back, it gives the same scenario as the old file read with the same method. Exit code
// 0 written, 2 bad arguments or a file that does not load (the message names the key).
#include <cstdio>
#include <exception>
#include <fsi/error.hpp>
#include <fsi/scenario.hpp>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

namespace {

constexpr int exit_ok = 0, exit_bad_input = 2;

int usage(const std::string& why) {
  std::fprintf(stderr,
               "fsi-migrate-scenario: %s\n"
               "usage: fsi-migrate-scenario OLD.json [--keep-old-defaults] > NEW.json\n",
               why.c_str());
  return exit_bad_input;
}

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw fsi::InputError(file, "", "cannot read the file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// `text` with "method": "chapter" as the first key of the top-level object.
std::string with_chapter_method(const std::string& text, const std::string& file) {
  const auto open = text.find('{');
  if (open == std::string::npos) throw fsi::InputError(file, "", "is not a JSON object");
  const bool empty = text.find_first_not_of(" \t\r\n", open + 1) != std::string::npos &&
                     text[text.find_first_not_of(" \t\r\n", open + 1)] == '}';
  return text.substr(0, open + 1) + "\n  \"method\": \"chapter\"" + (empty ? "\n" : ",") +
         text.substr(open + 1);
}

}  // namespace

int main(int argc, char** argv) {
  std::string file;
  bool keep_old_defaults = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      usage("writes OLD.json in the current scenario format");
      return exit_ok;
    }
    if (a == "--keep-old-defaults") {
      keep_old_defaults = true;
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option " + a);
    } else if (file.empty()) {
      file = a;
    } else {
      return usage("one scenario file only");
    }
  }
  if (file.empty()) return usage("no scenario file given");
  try {
    std::string text = read_text(file);
    // The old file read as the engine reads it now (renamed keys converted), with the
    // method the migrated file will have: what the result must reproduce.
    const nlohmann::json top = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const bool add_method = keep_old_defaults && top.is_object() && !top.contains("method");
    if (add_method) text = with_chapter_method(text, file);
    const fsi::Scenario old_read = fsi::parse_scenario(text, file);
    for (const fsi::RenamedKey& renamed : fsi::kRenamedNumericsKeys) {
      const std::regex key("\"" + std::string(renamed.old_key) + "\"(\\s*:\\s*)-?[0-9][0-9.eE+-]*");
      const int doublings = std::string(renamed.new_key) == "time_step_max_doublings"
                                ? old_read.numerics.time_step_max_doublings
                                : old_read.numerics.time_step_wall_zone_doublings;
      // "$1" then a digit would read as another group: the number goes in afterwards.
      text = std::regex_replace(text, key, "\"" + std::string(renamed.new_key) + "\"$1\x01");
      for (auto at = text.find('\x01'); at != std::string::npos; at = text.find('\x01'))
        text.replace(at, 1, std::to_string(doublings));
    }
    fsi::Scenario migrated = fsi::parse_scenario(text, file + " (migrated)");
    migrated.source = old_read.source;
    if (fsi::to_json(migrated) != fsi::to_json(old_read))
      throw fsi::InputError(file, "", "the migrated file would not give the same scenario (a renamed key written oddly?)");
    std::cout << text;
    return std::cout.good() ? exit_ok : exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-migrate-scenario: %s\n", e.what());
    return exit_bad_input;
  }
}
