// Longer steps away from the walls (numerics.time_step_max_doublings, core/time_step_choice.hpp):
// a ball falling far from the ground takes them and arrives where the constant-k run
// does; near the ground every step is k again, unless numerics.time_step_wall_zone_doublings
// lets a body nearly at rest there take longer ones.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenarios.hpp"

namespace {

/// Steps up to k 2^doublings, k = 5e-3 s.
fsi::Scenario falling_ball(int doublings) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.time_step_s = 5e-3;
  s.numerics.time_step_max_doublings = doublings;
  s.numerics.time_step_wall_zone_m = 0.03;
  s.numerics.time_step_patch_fraction = 1.0;  // the coarse patches are not what is tested here
  s.numerics.end_time_s = 0.2;
  s.gravity_mps2 = {0.0, -2.0};
  return s;
}

TEST(AdaptiveTimeStep, FarFromTheWallsStepsAreLongerAndEndWhereConstantStepsEnd) {
  fsi::Engine constant(falling_ball(0)), adaptive(falling_ball(1));
  int constant_steps = 0, adaptive_steps = 0;
  while (constant.state().time_s < 0.2 - 1e-9) {
    const fsi::StepReport r = constant.step();
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_DOUBLE_EQ(r.time_step_s, 5e-3);
    ++constant_steps;
  }
  while (adaptive.state().time_s < 0.2 - 1e-9) {
    const fsi::StepReport r = adaptive.step();
    ASSERT_TRUE(r.converged) << r.message;
    // The step-length controller starts at k and doubles after calm steps.
    if (adaptive_steps == 0) {
      EXPECT_DOUBLE_EQ(r.time_step_s, 5e-3);
    }
    // A power-of-two multiple of k, at most k 2^time_step_max_doublings.
    const double ratio = r.time_step_s / 5e-3;
    EXPECT_NEAR(ratio, std::exp2(std::round(std::log2(ratio))), 1e-12);
    EXPECT_LE(r.time_step_s, 1e-2 * (1 + 1e-12));
    ++adaptive_steps;
  }
  EXPECT_NEAR(adaptive.state().time_s, 0.2, 1e-9);
  // The ball is far from the ground: after the first step (k) every step 2k, but for a
  // last k to end at 0.2 s.
  EXPECT_EQ(2 * (adaptive_steps - 2) + 2, constant_steps);
  const fsi::Functionals& a = adaptive.state().functionals;
  const fsi::Functionals& c = constant.state().functionals;
  // Falling at about 0.3 m/s after 0.2 s: the same speed to 5 %, the same place to 1 mm.
  EXPECT_LT(c.mean_vy_mps, -0.1);
  EXPECT_NEAR(a.mean_vy_mps, c.mean_vy_mps, 0.05 * std::abs(c.mean_vy_mps));
  EXPECT_NEAR(a.bottom_y_m, c.bottom_y_m, 1e-3);
  EXPECT_LT(a.mass_error, 2.0 * c.mass_error + 1e-3);
}

TEST(AdaptiveTimeStep, NearAWallEveryStepIsK) {
  fsi::Scenario s = falling_ball(1);
  // Example 1's ground is y = -1: the ball's bottom 2 cm above it, inside the wall zone.
  s.body.center_m = {0.0, -1.0 + s.body.radius_m + 0.02};
  fsi::Engine engine(s);
  for (int i = 0; i < 3; ++i) {
    const fsi::StepReport r = engine.step();
    EXPECT_DOUBLE_EQ(r.time_step_s, 5e-3) << "t = " << r.time_s;
  }
}

// A ball set down 5 mm above the ground, inside the contact force's reach (dist_0 = 1 cm):
// it sinks at about 1 cm/s, slowed by the film, so with time_step_wall_zone_doublings it takes
// longer steps and follows the constant-k run (first order in the step: 0.14 mm ahead of
// it after 0.2 s, 1.3 mm down).
fsi::Scenario resting_ball(int doublings, int zone_doublings) {
  fsi::Scenario s = falling_ball(doublings);
  s.numerics.time_step_patch_fraction = 0.125;
  s.numerics.time_step_wall_zone_doublings = zone_doublings;
  s.numerics.end_time_s = 0.2;
  s.gravity_mps2 = {0.0, -0.5};
  s.contact.gamma_c = 800.0;
  s.contact.dist0_m = 1e-2;
  s.body.center_m = {0.0, -1.0 + s.body.radius_m + 5e-3};
  return s;
}

TEST(AdaptiveTimeStep, ABodyAtRestInTheWallZoneTakesLongerStepsOnlyWhenAllowed) {
  fsi::Engine constant(resting_ball(2, 0)), longer(resting_ball(2, 2));
  int constant_steps = 0, longer_steps = 0;
  double longest_s = 0.0;
  while (constant.state().time_s < 0.2 - 1e-9) {
    const fsi::StepReport r = constant.step();
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_DOUBLE_EQ(r.time_step_s, 5e-3);  // in the wall zone: k without the control
    ++constant_steps;
  }
  while (longer.state().time_s < 0.2 - 1e-9) {
    const fsi::StepReport r = longer.step();
    ASSERT_TRUE(r.converged) << r.message;
    longest_s = std::max(longest_s, r.time_step_s);
    ++longer_steps;
  }
  const fsi::Functionals& a = longer.state().functionals;
  const fsi::Functionals& c = constant.state().functionals;
  EXPECT_GT(c.min_distance_m, 0.0);
  EXPECT_LT(c.min_distance_m, 1e-2);  // it stayed in the contact force's reach
  EXPECT_GE(longest_s, 2e-2 * (1 - 1e-12));
  EXPECT_LE(2 * longer_steps, constant_steps);
  EXPECT_LT(c.mean_vy_mps, -5e-3);  // it moved: sinking in the film
  EXPECT_NEAR(a.bottom_y_m, c.bottom_y_m, 3e-4);
  EXPECT_NEAR(a.mean_vy_mps, c.mean_vy_mps, 0.1 * std::abs(c.mean_vy_mps));
  EXPECT_LT(a.mass_error, 2.0 * c.mass_error + 1e-3);
}

}  // namespace
