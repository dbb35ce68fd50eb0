// fsi-step: headless interactive stepping. Reads one command per line on stdin and
// answers each with exactly one JSON line on stdout (nothing else goes to stdout);
// errors are answers too ({"error": "..."}), never the end of the session. EOF or
// "quit" ends it. Commands: step [N], render FILE.png [field=..] [zoom=..] [size=WxH]
// [mesh=0|1], functionals, set KEY VALUE, numerics, save FILE, load FILE, remesh
// SCENARIO.json, scenario FILE.json, help, quit
// (see apps/common/step_session.hpp).
//
//   fsi-step SCENARIO.json [--set KEY=VALUE ...] [--exit-on-error]
//
// --exit-on-error is for scripts: after the first error answer the session ends (exit
// code 3), so that a failed "load CKPT" is not followed by "step 1000" from t = 0.
//
// Exit code: 0 after quit/EOF, 2 bad command line or scenario (message + usage), 3 a
// command failed under --exit-on-error.
//
// Examples:
//   fsi-step assets/scenarios/ball_drop.json                    # type: step 10, functionals
//   printf 'step 5\nrender out/t.png field=p\nquit\n' | fsi-step assets/scenarios/ball_drop.json
//   fsi-step tests/data/tiny_drop.json < tests/data/fsi_step_script.txt
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <fsi/error.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "heap_tuning.hpp"
#include "scenario_overrides.hpp"
#include "step_session.hpp"

namespace {

constexpr const char* kUsage =
    "usage: fsi-step SCENARIO.json [--set KEY=VALUE ...] [--exit-on-error]   (commands on stdin, "
    "'help' lists them)\n";

int usage(const std::string& why) {
  std::fprintf(stderr, "fsi-step: %s\n%s", why.c_str(), kUsage);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  fsi::app::keep_large_blocks_in_heap();  // see heap_tuning.hpp: a factorization per step
  std::string file;
  std::vector<fsi::app::Override> overrides;
  bool exit_on_error = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "-h" || a == "--help") {
        std::fputs(kUsage, stderr);
        return 0;
      }
      if (a == "--exit-on-error") {
        exit_on_error = true;
      } else if (a == "--set") {
        if (i + 1 >= argc) throw fsi::InputError("command line", a, "needs KEY=VALUE");
        overrides.push_back(fsi::app::parse_override(argv[++i]));
      } else if (a.size() > 1 && a[0] == '-') {
        throw fsi::InputError("command line", a, "unknown option");
      } else if (file.empty()) {
        file = a;
      } else {
        throw fsi::InputError("command line", a, "only one scenario file");
      }
    }
    if (file.empty()) throw fsi::InputError("command line", "", "need SCENARIO.json");
  } catch (const fsi::InputError& e) {
    return usage(e.what());
  }
  try {
    fsi::app::StepSession session(fsi::app::load_scenario_with_overrides(file, overrides));
    if (isatty(STDIN_FILENO)) std::fprintf(stderr, "%s\n", fsi::app::StepSession::hint());
    for (std::string line; !session.quit_requested() && std::getline(std::cin, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (const auto answer = session.handle(line)) {
        // Invalid UTF-8 echoed from a command is replaced, never an exception.
        std::cout << answer->dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace)
                  << std::endl;  // flushed: a script waits for each answer
        if (exit_on_error && answer->contains("error")) {
          std::fprintf(stderr, "fsi-step: stopped at the first error (--exit-on-error)\n");
          return 3;
        }
      }
    }
    return 0;
  } catch (const fsi::InputError& e) {
    return usage(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-step: %s\n", e.what());
    return 1;
  }
}
