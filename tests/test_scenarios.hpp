#pragma once
// Small scenarios shared by the tests (fast: a few hundred patches).
#include <fsi/scenario.hpp>

namespace fsi::testing {

/// Example 1 on a 4x coarser mesh (8+8 x 16 patches, 1089 nodes), by default with the
/// chapter's numerics: a test of one mechanism turns on what it tests, the others stay off.
inline Scenario coarse_example1(Method method = Method::chapter) {
  Scenario s = example1_scenario(method);
  s.name = "ball_drop_coarse";
  BlockSpec b;
  b.x = {AxisPiece{0.0, -1.0, 8, 0.05, 0.2}, AxisPiece{0.0, 1.0, 8, 0.05, 0.2}};
  b.y = {AxisPiece{-1.0, 0.5, 16, 0.00625, 0.3}};
  s.mesh.blocks = {b};
  s.numerics.time_step_s = 0.01;
  s.numerics.end_time_s = 0.2;
  return s;
}

/// The stiff ball of the chapter's contact study (mu_s = 3.2e6 Pa) on the coarse mesh,
/// 5 mm above the ground at 0.5 m/s, without a contact force: the fluid cushion slows it
/// to about 2 cm/s and it touches the ground at t = 0.04 s (step 20 of 2e-3 s).
inline Scenario stiff_ball_touching_down() {
  Scenario s = coarse_example1();
  s.body.center_m = {0.0, -1.0 + s.body.radius_m + 5e-3};
  s.body.initial_velocity_mps = {0.0, -0.5};
  s.solid.mu_pa = 3.2e6;
  s.solid.lambda_pa = 1.28e7;
  s.contact = {};
  s.numerics.time_step_s = 2e-3;
  s.numerics.end_time_s = 1.0;
  return s;
}

}  // namespace fsi::testing
