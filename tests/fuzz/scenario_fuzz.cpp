// libFuzzer harness for the scenario reader. Built and run by tools/fuzz-scenario.
//
// Any input must either give a valid Scenario or throw fsi::InputError. Anything else
// (another exception, a crash, a sanitizer report, a broken round trip) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "fsi/error.hpp"
#include "fsi/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const fsi::Scenario scenario = fsi::parse_scenario(text, "fuzz.json");
    // What was accepted must write out and read back to the same scenario.
    const std::string json = fsi::to_json(scenario);
    const fsi::Scenario back = fsi::parse_scenario(json, "fuzz-roundtrip.json");
    if (fsi::to_json(back) != json || fsi::fingerprint(back) != fsi::fingerprint(scenario)) {
      std::cerr << "round trip changed the scenario:\n" << json << "\n";
      std::abort();
    }
  } catch (const fsi::InputError&) {
    // Expected for bad input.
  }
  return 0;
}
