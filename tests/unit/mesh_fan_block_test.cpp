// Fan blocks (BlockSpec::y_right): a mapped block whose rows run from one node
// distribution on its left side to another on its right side, meeting a graded block on
// its left and a uniform one on its right node to node (the stairs' blocks beside a riser).
#include <gtest/gtest.h>

#include <cmath>

#include "fsi/scenario.hpp"
#include "mesh/patch_mesh.hpp"

namespace {

using fsi::AxisPiece;
using fsi::BlockSpec;
using fsi::MeshSpec;

/// Rows on [0, 1]: graded from `first` at y = 0 (or uniform with first = 0).
AxisPiece rows(double first, double last) { return AxisPiece{0.0, 1.0, 8, first, last}; }

/// [0,1]^2 graded rows | fan [1,3]x[0,1] | [3,4]x[0,1] uniform rows.
MeshSpec graded_fan_uniform(int refinements = 0) {
  BlockSpec left;
  left.x = {AxisPiece{0.0, 1.0, 4, 0.0, 0.0}};
  left.y = {rows(0.02, 0.3)};
  BlockSpec fan;
  fan.x = {AxisPiece{0.0, 1.0, 6, 0.0, 0.0}};
  fan.y = {rows(0.02, 0.3)};          // unit coordinates: the block is 1 m high
  fan.y_right = {rows(0.0, 0.0)};
  fan.mapped = true;
  fan.corners = {fsi::Point2{1.0, 0.0}, fsi::Point2{3.0, 0.0}, fsi::Point2{3.0, 1.0}, fsi::Point2{1.0, 1.0}};
  BlockSpec right;
  right.x = {AxisPiece{3.0, 4.0, 3, 0.0, 0.0}};
  right.y = {rows(0.0, 0.0)};
  MeshSpec spec;
  spec.blocks = {left, fan, right};
  spec.refinements = refinements;
  return spec;
}

TEST(FanBlock, MeetsDifferentRowsOnItsTwoSidesNodeToNode) {
  for (int refinements : {0, 1}) {
    const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(graded_fan_uniform(refinements), {});
    const int r = 1 << refinements;
    // One conforming mesh: (2 * 13 r + 1) x (2 * 8 r + 1) nodes, no side shared three times.
    EXPECT_EQ(mesh.num_nodes(), (2 * 13 * r + 1) * (2 * 8 * r + 1)) << refinements;
    int boundary = 0;
    for (const fsi::mesh::GridEdge& e : mesh.edges) boundary += e.boundary;
    EXPECT_EQ(boundary, 2 * (13 + 8) * r) << "interior sides left unshared: the blocks do not meet";
  }
}

TEST(FanBlock, RowsRunStraightFromTheLeftSideToTheRightSide) {
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(graded_fan_uniform(), {});
  int checked = 0;
  for (const fsi::mesh::Patch& p : mesh.patches) {
    const auto& x0 = mesh.nodes[p.node[0]];
    if (x0.x() < 1.0 - 1e-12 || x0.x() > 3.0 - 1e-12) continue;  // fan patches only
    // The bottom side's midpoint lies halfway between its corners (straight rows), the
    // patch is a trapezoid with vertical left and right sides.
    const auto& a = mesh.nodes[p.node[0]];
    const auto& m = mesh.nodes[p.node[1]];
    const auto& b = mesh.nodes[p.node[2]];
    EXPECT_NEAR((m - 0.5 * (a + b)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(mesh.nodes[p.node[6]].x(), a.x(), 1e-12);
    EXPECT_NEAR(mesh.nodes[p.node[8]].x(), b.x(), 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 6 * 8);
  // The first row is 2 cm thick at x = 1 (the graded block's) and 1/8 m at x = 3.
  auto first_row_top = [&](double x) {
    double y = 1.0;
    for (const fsi::mesh::Vec2& n : mesh.nodes)
      if (std::abs(n.x() - x) < 1e-12 && n.y() > 1e-12) y = std::min(y, n.y());
    return 2.0 * y;  // the lowest node above 0 is the first row's midpoint
  };
  EXPECT_NEAR(first_row_top(1.0), 0.02, 1e-9);
  EXPECT_NEAR(first_row_top(3.0), 0.125, 1e-9);
  EXPECT_NEAR(first_row_top(2.0), 0.5 * (0.02 + 0.125), 1e-9);
}

}  // namespace
