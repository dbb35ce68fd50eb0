// Which wall nodes inside the body let the solid go (core/contact_release.hpp): those
// on walls the body moves away from faster than kReleaseSpeed_mps, never a node that also
// lies on a wall the body does not leave, none for a body at rest or pressing on.
#include "core/contact_release.hpp"

#include <gtest/gtest.h>

#include "fe_test_meshes.hpp"

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
};

TEST(ContactRelease, ABodyLeavingTheFloorLetsGoOfItButNotOfTheCornerOnTheRightWall) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  const std::vector<char> r =
      fsi::core::released_wall_nodes(box.mesh, box.walls, solid, {0.0, 0.2}, {0.5, 0.5});
  ASSERT_EQ(static_cast<int>(r.size()), box.mesh.num_nodes());
  EXPECT_TRUE(r[box.node_at(0.0, 0.0)]);
  EXPECT_TRUE(r[box.node_at(0.25, 0.0)]);
  EXPECT_TRUE(r[box.node_at(0.75, 0.0)]);
  EXPECT_FALSE(r[box.node_at(1.0, 0.0)]) << "also on the right wall, which the body does not leave";
  EXPECT_FALSE(r[box.node_at(1.0, 0.5)]);
  EXPECT_FALSE(r[box.node_at(0.5, 0.5)]) << "not a wall node";
}

TEST(ContactRelease, MovingAwayFromBothWallsReleasesTheCornerToo) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  const std::vector<char> r =
      fsi::core::released_wall_nodes(box.mesh, box.walls, solid, {-0.3, 0.3}, {0.5, 0.5});
  ASSERT_FALSE(r.empty());
  EXPECT_TRUE(r[box.node_at(1.0, 0.0)]);
  EXPECT_TRUE(r[box.node_at(1.0, 1.0)]);
}

TEST(ContactRelease, NoneAtRestPressingOnOrOutsideTheSolid) {
  const Box box;
  const std::vector<char> solid(box.mesh.num_nodes(), 1);
  // Settling at 2 mm/s, below the release speed; pressing on the floor.
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, box.walls, solid, {0.0, 0.002}, {0.5, 0.5}).empty());
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, box.walls, solid, {0.0, -0.5}, {0.5, 0.5}).empty());
  // Leaving, but no wall node touches the solid.
  const std::vector<char> fluid(box.mesh.num_nodes(), 0);
  EXPECT_TRUE(fsi::core::released_wall_nodes(box.mesh, box.walls, fluid, {0.0, 0.5}, {0.5, 0.5}).empty());
}

}  // namespace
