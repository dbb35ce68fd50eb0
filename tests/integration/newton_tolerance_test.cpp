// Newton's relative tolerance must not depend on a stale row scale. When a factorization
// (and with it the row scale of the residual norm) was reused across steps, a row that had
// a tiny Jacobian in the old geometry made the step's initial residual look 1e4-1e6 times
// larger than it was, and a tolerance relative to that inflated number let such steps
// "converge" with a residual of 1e-3 while every other step got to 1e-8; near the ground
// the accumulated error broke the 4225-node Example 1 run. Newton measures the first
// residual again after every new factorization, and the engine now factorizes at every
// step's start: no first residual is measured in another step's scale.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include "test_scenarios.hpp"

namespace {

TEST(NewtonTolerance, ConvergedStepsAreConvergedWhateverTheirInitialResidual) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.body.center_m = {0.0, -1.0 + s.body.radius_m + 2e-2};  // 2 cm above the ground
  s.body.initial_velocity_mps = {0.0, -0.5};
  s.numerics.time_step_s = 0.005;
  fsi::Engine engine(s);
  int inflated = 0;  // steps whose first norm looks inflated by a stale scale
  for (int i = 0; i < 24; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << "step " << i << ": " << r.message;
    ASSERT_FALSE(r.residual_norms.empty());
    if (r.residual_norms.front() > 1e4) ++inflated;
    EXPECT_LT(r.residual_norms.back(), 1e-5)
        << "step " << i << " (t = " << engine.state().time_s << "): " << r.message;
  }
  // With the last step's factorization as Newton's first matrix, 2 or more of these
  // steps started above 1e4.
  EXPECT_EQ(inflated, 0);
}

}  // namespace
