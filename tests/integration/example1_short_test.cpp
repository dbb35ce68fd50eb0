// Short physics runs on a coarse Example 1 mesh (1089 nodes, k = 0.01 s).
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenarios.hpp"

namespace {

TEST(Quiescent, WithoutGravityEverythingStaysAtRest) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.gravity_mps2 = {0.0, 0.0};
  fsi::Engine engine(s);
  for (int i = 0; i < 5; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << r.message;
  }
  const Eigen::VectorXd& x = engine.state().solution;
  double vmax = 0, umax = 0, pmax = 0;
  for (int n = 0; n < x.size() / 5; ++n) {
    vmax = std::max({vmax, std::abs(x[5 * n]), std::abs(x[5 * n + 1])});
    umax = std::max({umax, std::abs(x[5 * n + 2]), std::abs(x[5 * n + 3])});
    pmax = std::max(pmax, std::abs(x[5 * n + 4]));
  }
  EXPECT_LT(vmax, 1e-12);
  EXPECT_LT(umax, 1e-12);
  EXPECT_LT(pmax, 1e-8);
}

TEST(Example1Short, BallFallsWithAddedMassAndConservesMass) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine engine(s);
  const double area0 = engine.state().functionals.solid_area_m2;
  const double bottom0 = engine.state().functionals.bottom_y_m;
  EXPECT_NEAR(bottom0, -0.4, 0.01);
  double previous_vy = 0.0;
  for (int i = 0; i < 20; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << "step " << i << ": " << r.message;
    ASSERT_TRUE(r.accepted);
    const fsi::Functionals& f = engine.state().functionals;
    EXPECT_LT(f.mean_vy_mps, previous_vy) << "the ball keeps accelerating downwards";
    previous_vy = f.mean_vy_mps;
  }
  const fsi::Functionals& f = engine.state().functionals;
  EXPECT_NEAR(engine.state().time_s, 0.2, 1e-12);
  // Gravity 0.5 m/s^2 on the solid only, rho_s = rho_f: the surrounding fluid must be
  // accelerated too, so the ball falls slower than in vacuum (|v| < g t = 0.1 m/s) but
  // clearly falls.
  EXPECT_LT(f.mean_vy_mps, -0.05);
  EXPECT_GT(f.mean_vy_mps, -0.1);
  EXPECT_LT(f.bottom_y_m, bottom0 - 0.004);
  EXPECT_NEAR(std::abs(f.mean_vx_mps), 0.0, 1e-6) << "symmetric set-up";
  EXPECT_LT(f.mass_error, 0.03);
  EXPECT_NEAR(f.solid_area_m2, area0, 0.02 * area0);
  EXPECT_GT(f.min_distance_m, 0.5);
}

}  // namespace
