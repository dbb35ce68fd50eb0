// Distance to the wall segments: perpendicular feet, end points, corners between walls.
#include "mesh/walls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using fsi::mesh::distance_to_walls;
using Vec2 = Eigen::Vector2d;

// A step: tread y = 1 for x in [0, 1], riser x = 1 down to y = 0, floor y = 0 to x = 2.
const std::vector<fsi::Segment2> kStep{
    {{0.0, 1.0}, {1.0, 1.0}}, {{1.0, 1.0}, {1.0, 0.0}}, {{1.0, 0.0}, {2.0, 0.0}}};

TEST(Walls, PerpendicularFootInsideASegment) {
  const auto d = distance_to_walls(kStep, Vec2(0.5, 1.3));
  EXPECT_NEAR(d.distance_m, 0.3, 1e-15);
  EXPECT_EQ(d.wall, 0);
  EXPECT_NEAR(d.nearest.x(), 0.5, 1e-15);
  EXPECT_NEAR(d.nearest.y(), 1.0, 1e-15);
}

TEST(Walls, BeyondTheEndTheEndPointIsNearest) {
  // Left of the tread's free end (0, 1): Euclidean distance to that end point.
  const auto d = distance_to_walls(kStep, Vec2(-0.3, 1.4));
  EXPECT_NEAR(d.distance_m, 0.5, 1e-15);
  EXPECT_EQ(d.wall, 0);
  EXPECT_NEAR(d.nearest.x(), 0.0, 1e-15);
  EXPECT_NEAR(d.nearest.y(), 1.0, 1e-15);
}

TEST(Walls, ConvexCornerOfAStepIsAPoint) {
  // Up and right of the stair's nose (1, 1): the nose is nearest, at distance 0.5,
  // although the point lies right of the tread and above the riser.
  const auto d = distance_to_walls(kStep, Vec2(1.3, 1.4));
  EXPECT_NEAR(d.distance_m, 0.5, 1e-15);
  EXPECT_NEAR(d.nearest.x(), 1.0, 1e-15);
  EXPECT_NEAR(d.nearest.y(), 1.0, 1e-15);
  EXPECT_TRUE(d.wall == 0 || d.wall == 1);
}

TEST(Walls, ConcaveCornerPicksTheNearerWall) {
  // In the corner between riser and floor: nearer to the riser (0.1) than the floor (0.2).
  auto d = distance_to_walls(kStep, Vec2(1.1, 0.2));
  EXPECT_NEAR(d.distance_m, 0.1, 1e-15);
  EXPECT_EQ(d.wall, 1);
  d = distance_to_walls(kStep, Vec2(1.3, 0.2));
  EXPECT_NEAR(d.distance_m, 0.2, 1e-15);
  EXPECT_EQ(d.wall, 2);
  EXPECT_NEAR(d.nearest.x(), 1.3, 1e-15);
}

TEST(Walls, InclinedSegment) {
  // The plane from (0, 1.4) to (1.2, 1.0): a point 0.5 above its middle along the normal.
  const std::vector<fsi::Segment2> plane{{{0.0, 1.4}, {1.2, 1.0}}};
  const Vec2 mid(0.6, 1.2), normal = Vec2(0.4, 1.2).normalized();
  const auto d = distance_to_walls(plane, mid + 0.5 * normal);
  EXPECT_NEAR(d.distance_m, 0.5, 1e-14);
  EXPECT_NEAR((d.nearest - mid).norm(), 0.0, 1e-14);
}

TEST(Walls, OnAWallAndWithoutWalls) {
  EXPECT_EQ(distance_to_walls(kStep, Vec2(1.0, 0.5)).distance_m, 0.0);
  const auto none = distance_to_walls({}, Vec2(0.0, 0.0));
  EXPECT_EQ(none.distance_m, std::numeric_limits<double>::infinity());
  EXPECT_EQ(none.wall, -1);
}

}  // namespace
