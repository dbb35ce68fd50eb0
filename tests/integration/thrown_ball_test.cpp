// A ball thrown at 1 m/s across a U-shaped box (walls left, right and below, open top)
// with the default numerics: its first steps converge. The first step adapts the initial
// potential flow to the walls with a pressure impulse of about +-5e4 Pa across the box;
// under the cavitation floor of -1e4 Pa Newton made no progress on it at any halving
// (Engine: the first step of a body that starts moving runs without the floor, and the
// second starts from p = 0).
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include "test_scenarios.hpp"

namespace {

TEST(ThrownBall, StartsInAUShapedBoxWithTheDefaults) {
  fsi::Scenario s = fsi::testing::coarse_example1(fsi::Method::fsi);
  s.walls = {fsi::Segment2{{-1.0, 0.5}, {-1.0, -1.0}}, fsi::Segment2{{-1.0, -1.0}, {1.0, -1.0}},
             fsi::Segment2{{1.0, -1.0}, {1.0, 0.5}}};
  s.body.center_m = {0.0, -0.3};
  s.body.radius_m = 0.3;
  s.body.initial_velocity_mps = {1.0, 0.0};
  s.numerics.time_step_s = 2e-3;
  fsi::Engine engine(s);
  for (int i = 0; i < 3; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.accepted) << "step " << i << ": " << r.message;
    EXPECT_TRUE(r.converged) << "step " << i << ": " << r.message;
  }
  // It keeps most of its speed: it starts with the flow it drives (0.75 m/s after three
  // steps; from fluid at rest 0.45 m/s, and unconverged steps).
  EXPECT_GT(engine.state().functionals.mean_vx_mps, 0.6);
}

}  // namespace
