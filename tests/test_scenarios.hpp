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

}  // namespace fsi::testing
