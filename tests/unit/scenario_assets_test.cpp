// Every scenario shipped in assets/scenarios loads, and the studies hold what they claim.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "fsi/error.hpp"
#include "fsi/scenario.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(FSI_SOURCE_DIR) / "assets" / "scenarios";

/// Nodes of a one-block mesh: 2 cells per patch and per refinement level, plus one.
long nodes(const fsi::Scenario& s) {
  long nx = 0, ny = 0;
  for (const auto& p : s.mesh.blocks.at(0).x) nx += p.patches;
  for (const auto& p : s.mesh.blocks.at(0).y) ny += p.patches;
  const long scale = 2L << s.mesh.refinements;
  return (scale * nx + 1) * (scale * ny + 1);
}

fsi::Scenario load(const std::string& relative) { return fsi::load_scenario(kAssets / relative); }

TEST(ScenarioAssets, EveryFileLoadsAndIsNamedUniquely) {
  std::map<std::string, fs::path> names;
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kAssets)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    fsi::Scenario s;
    try {
      s = fsi::load_scenario(entry.path());
    } catch (const fsi::InputError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    EXPECT_EQ(s.source, entry.path());
    EXPECT_TRUE(names.emplace(s.name, entry.path()).second) << "name used twice: " << s.name;
    // Every shipped scenario uses the default floor of -1e4 Pa.
    EXPECT_EQ(s.numerics.cavitation_pressure_pa, -1.0e4)
        << entry.path() << ": every shipped scenario uses the floor, got " << s.numerics.cavitation_pressure_pa;
    ++count;
  }
  EXPECT_GE(count, 16);
}

TEST(ScenarioAssets, BallDropIsExample1) {
  const fsi::Scenario s = load("ball_drop.json");
  EXPECT_EQ(nodes(s), 4225);
  EXPECT_EQ(s.numerics.time_step_s, 2e-3);
  EXPECT_EQ(s.numerics.end_time_s, 5.0);
  // The chapter's Example 1 with the fsi numerics, the defaults.
  EXPECT_EQ(s.method, fsi::Method::fsi);
  EXPECT_EQ(fsi::fingerprint(s), fsi::fingerprint(fsi::example1_scenario()));
  EXPECT_NE(fsi::fingerprint(s), fsi::fingerprint(fsi::example1_scenario(fsi::Method::chapter)));
}

TEST(ScenarioAssets, ShippedScenariosLeaveTheSolverToTheDefaults) {
  // Outside the stairs (tuned, tools/make-stairs-scenarios) a shipped scenario holds
  // physics, mesh, end time and output; of the numerics only the step and the end time.
  for (const auto& entry : fs::recursive_directory_iterator(kAssets)) {
    if (entry.path().extension() != ".json" || entry.path().parent_path().filename() == "stairs") continue;
    SCOPED_TRACE(entry.path().string());
    std::ifstream in(entry.path());
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_FALSE(j.contains("method"));
    if (!j.contains("numerics")) continue;
    for (const auto& item : j["numerics"].items()) {
      const std::string& key = item.key();
      EXPECT_TRUE(key == "time_step_s" || key == "end_time_s") << key;
    }
  }
}

TEST(ScenarioAssets, DemoAndFineMesh) {
  const fsi::Scenario demo = load("ball_drop_demo.json");
  EXPECT_EQ(nodes(demo), 2401);  // 49 x 49: the whole bounce in about two minutes
  EXPECT_EQ(demo.numerics.time_step_s, 4e-3);
  EXPECT_EQ(demo.numerics.end_time_s, 5.0);  // fall, film, rebound, second contact, rest
  EXPECT_EQ(demo.output.frame_every, 5);
  const fsi::Scenario fine = load("ball_drop_16641.json");
  EXPECT_EQ(nodes(fine), 16641);
  EXPECT_EQ(fine.numerics.time_step_s, 1e-3);
}

// The scenario's numerics are the default preset's with its own time step and end time.
void expect_default_numerics_but_the_step(const fsi::Scenario& s) {
  fsi::Scenario expected = s;
  expected.numerics = fsi::example1_scenario().numerics;
  expected.numerics.time_step_s = s.numerics.time_step_s;
  expected.numerics.end_time_s = s.numerics.end_time_s;
  EXPECT_EQ(fsi::to_json(s), fsi::to_json(expected));
}

TEST(ScenarioAssets, MaterialStudy) {
  for (const char* mu : {"5e4", "1e5", "2e5", "4e5", "8e5", "1.6e6", "3.2e6"}) {
    const fsi::Scenario s = load(std::string("materials/mu_") + mu + ".json");
    EXPECT_EQ(s.solid.mu_pa, std::stod(mu));
    EXPECT_DOUBLE_EQ(s.solid.lambda_pa, 4.0 * s.solid.mu_pa);
    EXPECT_EQ(s.contact.gamma_c, 0.0);
    // A quarter of Example 1's step, the default numerics otherwise (docs/validation.md,
    // "Material study").
    EXPECT_EQ(s.numerics.time_step_s, 5e-4);
    expect_default_numerics_but_the_step(s);
  }
}

TEST(ScenarioAssets, ContactStudy) {
  for (const char* d0 : {"1e-3", "5e-3", "1e-2"}) {
    for (const char* gamma : {"800", "1600"}) {
      const fsi::Scenario s = load(std::string("contact/d0_") + d0 + "_g" + gamma + ".json");
      EXPECT_EQ(s.contact.dist0_m, std::stod(d0));
      EXPECT_EQ(s.contact.gamma_c, std::stod(gamma));
      EXPECT_EQ(s.solid.mu_pa, 3.2e6);
      EXPECT_EQ(s.solid.lambda_pa, 1.28e7);
      EXPECT_EQ(s.numerics.time_step_s, 5e-4);  // a quarter of Example 1's (docs/validation.md)
      expect_default_numerics_but_the_step(s);
    }
  }
}

}  // namespace
