// Which wall nodes inside the body let the solid go (core/contact_release.hpp): those
// of contact patches that the wall pulls as a whole, on every wall through the node; none
// where it pushes.
#include "core/contact_release.hpp"

#include <gtest/gtest.h>

#include "fe_test_meshes.hpp"
#include "fsi/state.hpp"

namespace {

// The unit square, 2 x 2 patches (5 x 5 nodes), with a floor (y = 0) and a right wall
// (x = 1); the body's centroid inside.
struct Box {
  std::vector<fsi::Segment2> walls{{{0.0, 0.0}, {1.0, 0.0}}, {{1.0, 0.0}, {1.0, 1.0}}};
  fsi::mesh::PatchMesh mesh = fsi::test::block_mesh(2, 2, 1.0, 1.0, false, {}, 0, walls);
  int node_at(double x, double y) const {
    for (int n = 0; n < mesh.num_nodes(); ++n)
      if ((mesh.nodes[n] - Eigen::Vector2d(x, y)).norm() < 1e-12) return n;
    return -1;
  }
  /// The same wall force [N/m] at every node (only the wall nodes' count).
  Eigen::VectorXd force(double vx, double vy) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      x[fsi::kFieldsPerNode * n + fsi::kVx] = vx;
      x[fsi::kFieldsPerNode * n + fsi::kVy] = vy;
    }
    return x;
  }
};

TEST(ContactRelease, ASolidPulledOffTheFloorIsLetGoButNotAtTheCornerOnTheRightWall) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  // The wall pulls downwards: the solid is lifting off the floor.
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(0.0, -1.0));
  ASSERT_EQ(static_cast<int>(r.size()), box.mesh.num_nodes());
  EXPECT_TRUE(r[box.node_at(0.0, 0.0)]);
  EXPECT_TRUE(r[box.node_at(0.25, 0.0)]);
  EXPECT_TRUE(r[box.node_at(0.75, 0.0)]);
  EXPECT_FALSE(r[box.node_at(1.0, 0.0)]) << "the right wall does not pull there";
  EXPECT_FALSE(r[box.node_at(1.0, 0.5)]);
  EXPECT_FALSE(r[box.node_at(0.5, 0.5)]) << "not a wall node";
}

TEST(ContactRelease, PulledTowardsBothWallsReleasesTheCornerToo) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(1.0, -1.0));
  ASSERT_FALSE(r.empty());
  EXPECT_TRUE(r[box.node_at(1.0, 0.0)]);
  EXPECT_TRUE(r[box.node_at(1.0, 0.5)]);
  EXPECT_TRUE(r[box.node_at(0.5, 0.0)]);
}

TEST(ContactRelease, APatchThatPushesAsAWholeIsHeldWhereOneNodePulls) {
  // Rocking on the floor: the wall pulls under the left end and pushes harder under the
  // rest of the same contact patch. Releasing its ends one by one while the rest presses
  // on made the stiff ball's third landing chatter (assets/scenarios/impacts/).
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  Eigen::VectorXd f = box.force(0.0, 2.0);
  f[fsi::kFieldsPerNode * box.node_at(0.0, 0.0) + fsi::kVy] = -0.5;
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, solid, solid, f).empty());
  f[fsi::kFieldsPerNode * box.node_at(0.25, 0.0) + fsi::kVy] = -5.0;
  f[fsi::kFieldsPerNode * box.node_at(0.5, 0.0) + fsi::kVy] = -5.0;
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, solid, solid, f);
  ASSERT_FALSE(r.empty()) << "the floor patch pulls as a whole: -10.5 + 2 + 2 N/m";
  for (double x : {0.0, 0.25, 0.5, 0.75}) EXPECT_TRUE(r[box.node_at(x, 0.0)]) << x;
  EXPECT_FALSE(r[box.node_at(1.0, 0.0)]) << "on the right wall too, which does not pull";
}

TEST(ContactRelease, EachContactPatchDecidesForItself) {
  // The solid touches the floor left and right of x = 0.5, not at it: two patches, the
  // left one pulled, the right one pushed.
  const Box box;
  std::vector<char> solid(box.mesh.num_nodes(), 1);
  solid[box.node_at(0.5, 0.0)] = 0;
  Eigen::VectorXd f = box.force(0.0, 1.0);
  for (double x : {0.0, 0.25}) f[fsi::kFieldsPerNode * box.node_at(x, 0.0) + fsi::kVy] = -1.0;
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, solid, solid, f);
  ASSERT_FALSE(r.empty());
  EXPECT_TRUE(r[box.node_at(0.0, 0.0)]);
  EXPECT_TRUE(r[box.node_at(0.25, 0.0)]);
  EXPECT_FALSE(r[box.node_at(0.5, 0.0)]) << "not touching";
  EXPECT_FALSE(r[box.node_at(0.75, 0.0)]);
  EXPECT_FALSE(r[box.node_at(1.0, 0.0)]);
}

TEST(ContactRelease, APatchTheSolidReachesOnlyNowIsHeld) {
  // The floor pulls everywhere, but at x = 0.75 the solid touches only from this step on:
  // the floor's patch (one, through x = 0.75) is held; the right wall's is let go.
  const Box box;
  const std::vector<char> now(box.mesh.num_nodes(), 1);
  std::vector<char> before = now;
  before[box.node_at(0.75, 0.0)] = 0;
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, now, before, box.force(1.0, -1.0));
  ASSERT_FALSE(r.empty());
  for (double x : {0.0, 0.25, 0.5, 0.75, 1.0}) EXPECT_FALSE(r[box.node_at(x, 0.0)]) << x;
  EXPECT_TRUE(r[box.node_at(1.0, 0.5)]);
}

TEST(ContactRelease, TurnedRoundHoldsTheReleasedAndReleasesTheHeld) {
  // The floor pulls, the right wall pushes: turned round, the right wall's nodes (the
  // corner among them) are released and the floor's held.
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  const std::vector<char> r = fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(-1.0, -1.0));
  ASSERT_TRUE(r[box.node_at(0.5, 0.0)]);
  const std::vector<char> t = fsi::core::turned_round(box.mesh, solid, r);
  ASSERT_FALSE(t.empty());
  EXPECT_FALSE(t[box.node_at(0.5, 0.0)]);
  EXPECT_TRUE(t[box.node_at(1.0, 0.0)]);
  EXPECT_TRUE(t[box.node_at(1.0, 0.5)]);
  EXPECT_FALSE(t[box.node_at(0.5, 0.5)]) << "not a wall node";
  // Nothing released: every touching wall node is; nothing touching: none.
  const std::vector<char> all = fsi::core::turned_round(box.mesh, solid, {});
  ASSERT_FALSE(all.empty());
  EXPECT_TRUE(all[box.node_at(0.0, 0.0)]);
  EXPECT_TRUE(fsi::core::turned_round(box.mesh, std::vector<char>(box.mesh.num_nodes(), 0), {}).empty());
}

TEST(ContactRelease, NoneWhereTheWallPushesOrNothingTouches) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(0.0, 3.0)).empty()) << "a body resting";
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(0.0, 0.0)).empty());
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, solid, solid, box.force(-1.0, 0.0)).empty())
      << "sheared along the floor, pressed onto the right wall";
  const std::vector<char> fluid(box.mesh.num_nodes(), 0);
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, fluid, fluid, box.force(0.0, -1.0)).empty());
}

}  // namespace
