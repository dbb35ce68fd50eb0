// The chapter's Example 1 as the default scenario (docs/method.md, "Example 1"), and the
// numerics presets (fsi: the member initialisers; chapter: the chapter's method).
#include "fsi/scenario.hpp"

namespace fsi {

NumericsSpec numerics_for(Method method) {
  NumericsSpec n;  // the member initialisers: the fsi preset
  if (method == Method::chapter) {
    // The chapter's method: every addition of ours off, Newton as in its Table 12.1 runs.
    n.time_step_max_doublings = 0;
    n.time_step_wall_zone_doublings = 0;
    n.time_error_tolerance_m = 0.0;
    n.newton_rel_tol = 1.0e-8;
    n.reuse_contraction = 0.2;
    n.newton_budget = 8;
    n.cavitation_pressure_pa = 0.0;
    n.backflow_beta = 0.0;
    n.rereference_angle_rad = 0.0;
    n.cut_align_fraction = 0.0;
    n.failure_policy = FailurePolicy::accept_and_flag;
  }
  return n;
}

Scenario example1_scenario(Method method) {
  Scenario s;  // materials, body and gravity: member defaults = Example 1
  s.method = method;
  s.numerics = numerics_for(method);
  s.name = "ball_drop";
  BlockSpec block;
  // Patch widths 0.025 + 0.005 i (i = 0..15) from the centre outwards on each side:
  // linearly growing widths from 0.025 m to 0.1 m over 1 m.
  block.x = {AxisPiece{0.0, -1.0, 16, 0.025, 0.1}, AxisPiece{0.0, 1.0, 16, 0.025, 0.1}};
  // Heights growing smoothly from 0.003125 m at the ground to about 0.15 m at the top.
  block.y = {AxisPiece{-1.0, 0.5, 32, 0.003125, 0.15}};
  s.mesh.blocks = {block};
  s.mesh.refinements = 0;
  s.walls = {Segment2{{-1.0, -1.0}, {1.0, -1.0}}};  // ground; the rest is open
  return s;
}

}  // namespace fsi
