// The failure policy as a pure function (core/step_policy.hpp): which Newton attempt a
// step accepts, retries or rejects. The rule for an attempt whose
// Newton never moved its iterate is never accepted, whatever the policy.
#include "core/step_policy.hpp"

#include <gtest/gtest.h>

namespace {

using fsi::core::AttemptAction;
using fsi::core::judge_attempt;

fsi::solve::NewtonResult attempt(bool converged, int accepted_iterates, double relative_residual,
                                 double final_residual = 1e-9) {
  fsi::solve::NewtonResult r;
  r.norms = {final_residual / relative_residual, final_residual};
  r.converged = converged;
  r.accepted_iterates = accepted_iterates;
  r.iterations = accepted_iterates + 1;
  r.relative_residual = relative_residual;
  return r;
}

fsi::NumericsSpec policy(fsi::FailurePolicy p, double accept_flagged_reduction = 0.0) {
  fsi::NumericsSpec n;
  n.failure_policy = p;
  n.max_halvings = 3;
  n.accept_flagged_reduction = accept_flagged_reduction;
  return n;
}

TEST(StepPolicy, AConvergedAttemptIsAcceptedUnderEveryPolicy) {
  for (auto p : {fsi::FailurePolicy::accept_and_flag, fsi::FailurePolicy::halve_step,
                 fsi::FailurePolicy::stop_and_rollback}) {
    const auto v = judge_attempt(policy(p), attempt(true, 3, 1e-9), true, 0, false);
    EXPECT_EQ(v.action, AttemptAction::accept);
    EXPECT_FALSE(v.flagged_early);
  }
  // Converged at its start (the residual was below abs_tol): no iterate needed.
  EXPECT_EQ(judge_attempt(policy(fsi::FailurePolicy::halve_step), attempt(true, 0, 1.0), true, 0, false).action,
            AttemptAction::accept);
}

TEST(StepPolicy, AcceptAndFlagKeepsAnUnconvergedAttemptThatMovedButNotOneThatDidNot) {
  const auto n = policy(fsi::FailurePolicy::accept_and_flag);
  EXPECT_EQ(judge_attempt(n, attempt(false, 2, 0.3), true, 0, false).action, AttemptAction::accept);
  EXPECT_EQ(judge_attempt(n, attempt(false, 0, 1.0), true, 0, false).action, AttemptAction::give_up);
  EXPECT_EQ(judge_attempt(n, attempt(false, 2, 0.3), false, 0, false).action, AttemptAction::give_up);
}

TEST(StepPolicy, HalveStepRetriesThenAcceptsTheBestButNeverAFrozenAttempt) {
  const auto n = policy(fsi::FailurePolicy::halve_step);
  auto v = judge_attempt(n, attempt(false, 2, 1e-3), true, 0, false);
  EXPECT_EQ(v.action, AttemptAction::retry_halved);
  EXPECT_TRUE(v.candidate);
  v = judge_attempt(n, attempt(false, 0, 1.0), true, 1, true);
  EXPECT_EQ(v.action, AttemptAction::retry_halved);
  EXPECT_FALSE(v.candidate) << "an attempt that did not move is no candidate";
  // The last halving: the best earlier attempt is accepted even if this one is frozen...
  EXPECT_EQ(judge_attempt(n, attempt(false, 0, 1.0), true, 3, true).action, AttemptAction::accept_best);
  // ... but if no attempt moved, the step is rejected rather than frozen.
  EXPECT_EQ(judge_attempt(n, attempt(false, 0, 1.0), true, 3, false).action, AttemptAction::give_up);
  EXPECT_EQ(judge_attempt(n, attempt(false, 1, 0.5), true, 3, false).action, AttemptAction::accept_best);
}

TEST(StepPolicy, AcceptFlaggedReductionAcceptsAtOnceOnlyAttemptsThatGotFarEnoughDown) {
  const auto n = policy(fsi::FailurePolicy::halve_step, 1e-4);
  auto v = judge_attempt(n, attempt(false, 7, 5e-5), true, 0, false);
  EXPECT_EQ(v.action, AttemptAction::accept);
  EXPECT_TRUE(v.flagged_early);
  EXPECT_EQ(judge_attempt(n, attempt(false, 7, 5e-3), true, 0, false).action, AttemptAction::retry_halved);
  // Far down from a huge start but nowhere near a solution (step 288 of the corner probe,
  // a corner contact: 74 -> 8.2e-4): halved, not accepted.
  EXPECT_EQ(n.accept_flagged_max_residual, 1e-4);
  v = judge_attempt(n, attempt(false, 17, 1.1e-5, 8.2e-4), true, 0, false);
  EXPECT_EQ(v.action, AttemptAction::retry_halved);
  EXPECT_FALSE(v.flagged_early);
  EXPECT_TRUE(v.candidate);
}

TEST(StepPolicy, StopAndRollbackRejectsEveryUnconvergedAttempt) {
  const auto n = policy(fsi::FailurePolicy::stop_and_rollback);
  EXPECT_EQ(judge_attempt(n, attempt(false, 5, 1e-7), true, 0, false).action, AttemptAction::give_up);
}

}  // namespace
