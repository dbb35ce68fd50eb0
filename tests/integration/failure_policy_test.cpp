// halve_step retries an unconverged step with k/2, k/4, ...; accept_flagged_reduction lets
// it accept (and flag) an attempt that got its residual far enough down at once, since
// where Newton stalls just short of the tolerance smaller steps stall alike.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "test_scenarios.hpp"

namespace {

int halvings(const fsi::StepReport& r) {
  return static_cast<int>(std::count_if(r.events.begin(), r.events.end(), [](const fsi::StepEvent& e) {
    return e.kind == fsi::StepEvent::Kind::step_halved;
  }));
}

/// Example 1 falling for a few steps, then with a budget of one Newton iteration per
/// attempt: no step can converge, and the one iteration takes the residual well down.
fsi::Engine one_iteration_per_attempt(double accept_flagged_reduction, double accept_flagged_max_residual = 1e6) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine engine(s);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(engine.step().converged);
  fsi::NumericsSpec n = s.numerics;
  n.newton_budget = 1;
  n.failure_policy = fsi::FailurePolicy::halve_step;
  n.max_halvings = 2;
  n.accept_flagged_reduction = accept_flagged_reduction;
  n.accept_flagged_max_residual = accept_flagged_max_residual;
  engine.set_numerics(n);
  return engine;
}

TEST(FailurePolicy, HalveStepRetriesEveryFailureByDefault) {
  fsi::Engine engine = one_iteration_per_attempt(0.0);
  const fsi::StepReport r = engine.step();
  EXPECT_FALSE(r.converged) << r.message;
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(halvings(r), 2) << r.message;
  EXPECT_EQ(r.message.find("accept_flagged_reduction"), std::string::npos) << r.message;
}

TEST(FailurePolicy, TheMessageOfAStepAcceptedAsTheBestGivesThatAttemptsResidual) {
  // One Newton iteration per attempt: every attempt is [start, end] in residual_norms, and
  // the step keeps the one that reduced its residual most, not the last.
  fsi::Engine engine = one_iteration_per_attempt(0.0);
  const fsi::StepReport r = engine.step();
  ASSERT_TRUE(r.accepted);
  ASSERT_EQ(r.residual_norms.size(), 6u) << r.message;
  std::size_t best = 0;
  for (std::size_t a = 1; a < 3; ++a)
    if (r.residual_norms[2 * a + 1] / r.residual_norms[2 * a] <
        r.residual_norms[2 * best + 1] / r.residual_norms[2 * best])
      best = a;
  std::ostringstream expected;
  expected << "residual " << r.residual_norms[2 * best] << " -> " << r.residual_norms[2 * best + 1];
  EXPECT_NE(r.message.find(expected.str()), std::string::npos) << "attempt " << best << ": " << r.message;
  EXPECT_NE(r.message.find("accepted the best of 3 attempt(s)"), std::string::npos) << r.message;
}

TEST(FailurePolicy, AStepThatStalledFarDownIsAcceptedWithoutHalving) {
  fsi::Engine engine = one_iteration_per_attempt(0.5);
  const fsi::StepReport r = engine.step();
  EXPECT_FALSE(r.converged) << "flagged, not converged: " << r.message;
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(halvings(r), 0) << r.message;
  EXPECT_DOUBLE_EQ(r.time_step_s, engine.scenario().numerics.time_step_s);
  EXPECT_NE(r.message.find("accept_flagged_reduction"), std::string::npos) << r.message;
  ASSERT_GE(r.residual_norms.size(), 2u);
  EXPECT_LT(r.residual_norms.back(), 0.5 * r.residual_norms.front()) << r.message;
}

TEST(FailurePolicy, ABestAttemptAboveTheBoundIsRejectedNotAccepted) {
  fsi::Engine engine = one_iteration_per_attempt(0.0);
  fsi::NumericsSpec n = engine.scenario().numerics;
  n.accept_best_max_residual = 1e-30;  // no attempt of one iteration gets there
  engine.set_numerics(n);
  const fsi::State before = engine.state();
  const fsi::StepReport r = engine.step();
  EXPECT_FALSE(r.accepted) << r.message;
  EXPECT_EQ(halvings(r), 2) << "halved as usual before giving up: " << r.message;
  EXPECT_EQ(engine.state().time_s, before.time_s);
  EXPECT_EQ(engine.state().solution, before.solution);
  EXPECT_NE(r.message.find("accept_best_max_residual"), std::string::npos) << r.message;
  // Above the best's residual the bound changes nothing: accepted and flagged.
  n.accept_best_max_residual = 1e6;
  engine.set_numerics(n);
  const fsi::StepReport again = engine.step();
  EXPECT_TRUE(again.accepted) << again.message;
  EXPECT_FALSE(again.converged);
  EXPECT_GT(engine.state().time_s, before.time_s);
}

TEST(FailurePolicy, AStepThatDidNotGetFarEnoughDownIsStillHalved) {
  // One Newton iteration does not take the residual down by 1e-12: halved as before.
  fsi::Engine engine = one_iteration_per_attempt(1e-12);
  const fsi::StepReport r = engine.step();
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(halvings(r), 2) << r.message;
}

TEST(FailurePolicy, AStepFarDownFromAHugeStartIsStillHalved) {
  // Far enough down relatively (0.5), but its final residual is above the absolute bound:
  // halved as a failed step (real contact at a corner).
  fsi::Engine engine = one_iteration_per_attempt(0.5, 1e-30);
  const fsi::StepReport r = engine.step();
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(halvings(r), 2) << r.message;
  EXPECT_EQ(r.message.find("accept_flagged_reduction"), std::string::npos) << r.message;
}

TEST(FailurePolicy, AnUnconvergedStepSaysWhereItsResidualIsLargest) {
  fsi::Engine engine = one_iteration_per_attempt(0.5);
  const fsi::StepReport r = engine.step();
  ASSERT_FALSE(r.converged);
  const fsi::ResidualPeak& w = r.largest_residual;
  ASSERT_GE(w.node, 0) << r.message;
  // The peak is the final scaled norm, at a node of the box ([-1, 1] x [-1, 0.5] m).
  EXPECT_DOUBLE_EQ(w.scaled_value, r.residual_norms.back());
  EXPECT_GE(w.where_m.x, -1.0);
  EXPECT_LE(w.where_m.x, 1.0);
  EXPECT_GE(w.where_m.y, -1.0);
  EXPECT_LE(w.where_m.y, 0.5);
  EXPECT_TRUE(std::string(w.phase) == "fluid" || std::string(w.phase) == "solid" ||
              std::string(w.phase) == "interface")
      << w.phase;
  EXPECT_NE(r.message.find(std::string("largest residual: ") + fsi::equation_name(w.equation)),
            std::string::npos)
      << r.message;
}

TEST(FailurePolicy, AConvergedStepKeepsItsMessageShort) {
  fsi::Engine engine(fsi::testing::coarse_example1());
  const fsi::StepReport r = engine.step();
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.message.find("largest residual"), std::string::npos) << r.message;
}

}  // namespace
