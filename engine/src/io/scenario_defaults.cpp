// The chapter's Example 1 as the default scenario (docs/method.md, "Example 1").
#include "fsi/scenario.hpp"

namespace fsi {

Scenario example1_scenario() {
  Scenario s;  // materials, body, gravity and numerics: member defaults = Example 1
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
