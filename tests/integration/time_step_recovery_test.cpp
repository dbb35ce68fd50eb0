// numerics.recovery_steps: after a step accepted at a reduced k the engine stays there and
// doubles back towards the scenario's k only at step numbers divisible by recovery_steps.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <vector>

#include "test_scenarios.hpp"

namespace {

/// The k of each of `steps` steps of an engine whose last step was taken at k / 4 (as
/// after two halvings), with the given recovery_steps.
std::vector<double> steps_after_a_reduction(int recovery_steps, int steps) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.failure_policy = fsi::FailurePolicy::halve_step;
  s.numerics.recovery_steps = recovery_steps;
  fsi::Engine engine(s);
  fsi::State reduced = engine.state();
  reduced.step = 1;  // step numbers 1, 2, ...: the doubling points are 4 and 8 for 4
  reduced.time_step_s = 0.25 * s.numerics.time_step_s;
  engine.set_state(reduced);
  std::vector<double> k;
  for (int i = 0; i < steps; ++i) {
    const fsi::StepReport r = engine.step();
    EXPECT_TRUE(r.accepted && r.converged) << r.message;
    k.push_back(r.time_step_s / s.numerics.time_step_s);
  }
  return k;
}

TEST(TimeStepRecovery, StaysReducedAndDoublesBackAtMultiplesOfRecoverySteps) {
  // Steps 2, 3, 4 at k/4; at step number 4 (divisible by 4) the next is k/2 (steps 5-8);
  // at 8, k again.
  const std::vector<double> want{0.25, 0.25, 0.25, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0};
  EXPECT_EQ(steps_after_a_reduction(4, 9), want);
}

TEST(TimeStepRecovery, ZeroTriesTheFullStepAtOnce) {
  EXPECT_EQ(steps_after_a_reduction(0, 2), (std::vector<double>{1.0, 1.0}));
}

}  // namespace
