// Engine::set_numerics (fsi-step's `set`) changes every numerical parameter it is given,
// including the stabilization weights the monolithic system keeps, and checks them like
// a scenario file's.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include <fsi/error.hpp>

#include "test_scenarios.hpp"

namespace {

bool bit_identical(const fsi::Engine& a, const fsi::Engine& b) {
  const Eigen::VectorXd& x = a.state().solution;
  const Eigen::VectorXd& y = b.state().solution;
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), sizeof(double) * x.size()) == 0;
}

/// Steps three engines once: one with the scenario's numerics, one built with `changed`,
/// one switched to `changed` by set_numerics before its first step.
void expect_set_numerics_acts_like_the_scenario(const fsi::NumericsSpec& changed) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine unchanged(s);
  fsi::Engine switched(s);
  switched.set_numerics(changed);
  s.numerics = changed;
  fsi::Engine built(s);
  unchanged.step();
  switched.step();
  built.step();
  EXPECT_TRUE(bit_identical(switched, built)) << "set_numerics differs from a scenario with these numerics";
  EXPECT_FALSE(bit_identical(switched, unchanged)) << "set_numerics had no effect";
}

TEST(SetNumerics, ChangesThePressureStabilization) {
  fsi::NumericsSpec n = fsi::testing::coarse_example1().numerics;
  n.cip_gamma *= 10.0;
  expect_set_numerics_acts_like_the_scenario(n);
}

TEST(SetNumerics, ChangesTheSolidVelocityStabilization) {
  fsi::NumericsSpec n = fsi::testing::coarse_example1().numerics;
  n.solid_alpha *= 10.0;
  expect_set_numerics_acts_like_the_scenario(n);
}

TEST(SetNumerics, RefusesAValueOutOfRangeAndKeepsTheOldOnes) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine reference(s), engine(s);
  fsi::NumericsSpec n = s.numerics;
  n.cip_gamma = -1.0;
  try {
    engine.set_numerics(n);
    FAIL() << "a negative cip_gamma was accepted";
  } catch (const fsi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cip_gamma"), std::string::npos) << e.what();
  }
  reference.step();
  engine.step();
  EXPECT_TRUE(bit_identical(reference, engine));
}

TEST(SetNumerics, CheckpointsSavedAfterwardsCarryTheNewNumerics) {
  const fsi::Scenario original = fsi::testing::coarse_example1();
  fsi::Engine engine(original);
  fsi::NumericsSpec n = original.numerics;
  n.cavitation_pressure_pa = -3e4;
  engine.set_numerics(n);
  EXPECT_EQ(engine.scenario().numerics.cavitation_pressure_pa, -3e4);
  engine.step();
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "fsi_set_numerics_test.ckpt";
  fsi::save_checkpoint(engine, file);
  fsi::Scenario changed = original;
  changed.numerics = n;
  fsi::Engine same_numerics(changed);
  EXPECT_NO_THROW(fsi::load_checkpoint(same_numerics, file));
  EXPECT_TRUE(bit_identical(engine, same_numerics));
  fsi::Engine old_numerics(original);
  EXPECT_THROW(fsi::load_checkpoint(old_numerics, file), fsi::InputError)
      << "a checkpoint made with changed numerics loaded into the original scenario";
  std::filesystem::remove(file);
}

}  // namespace

namespace {

TEST(SetNumerics, ACheckpointGoesOnWithOtherSolverControls) {
  // The Newton budget, tolerances and failure policy steer the solver, not the problem:
  // a run may continue from its checkpoint with others (not so the physics, above).
  const fsi::Scenario original = fsi::testing::coarse_example1();
  fsi::Engine engine(original);
  engine.step();
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "fsi_set_numerics_controls_test.ckpt";
  fsi::save_checkpoint(engine, file);
  fsi::Scenario controls = original;
  controls.numerics.failure_policy = fsi::FailurePolicy::stop_and_rollback;
  controls.numerics.newton_budget = original.numerics.newton_budget + 4;
  controls.numerics.max_halvings = 1;
  fsi::Engine continued(controls);
  EXPECT_NO_THROW(fsi::load_checkpoint(continued, file));
  EXPECT_TRUE(bit_identical(engine, continued));
  EXPECT_TRUE(continued.step().accepted);
  std::filesystem::remove(file);
}

}  // namespace
