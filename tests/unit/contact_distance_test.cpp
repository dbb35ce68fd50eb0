// Tread edges push like flat walls (core/contact_distance.hpp): a ball at a gap g from a
// convex wall corner gets about the penalty force it gets at the same gap from a flat
// wall, while the chapter's distance to the corner point gives it a small fraction of
// that; flat walls, concave corners and everything out of reach keep the plain distance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/contact_distance.hpp"
#include "mesh/walls.hpp"

namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kGammaC = 1e4, kDist0 = 1e-2, kRadius = 0.4;

/// A stair: tread y = 0.5 for x <= 3.2, riser x = 3.2 below it (the corner (3.2, 0.5)).
std::vector<fsi::Segment2> stair() { return {{{2.2, 0.5}, {3.2, 0.5}}, {{3.2, 0.5}, {3.2, 0.0}}}; }
/// A flat floor y = 0.5.
std::vector<fsi::Segment2> floor_wall() { return {{{0.0, 0.5}, {6.0, 0.5}}}; }

/// The circle of radius kRadius about `centre` as 2000 interface chords.
std::vector<fsi::fe::InterfaceSegment> circle(const Vec2& centre) {
  std::vector<fsi::fe::InterfaceSegment> segments;
  constexpr int kChords = 2000;
  for (int i = 0; i < kChords; ++i) {
    const double a0 = 2.0 * std::numbers::pi * i / kChords, a1 = 2.0 * std::numbers::pi * (i + 1) / kChords;
    segments.push_back({centre + kRadius * Vec2(std::cos(a0), std::sin(a0)),
                        centre + kRadius * Vec2(std::cos(a1), std::sin(a1))});
  }
  return segments;
}

double pressure(double d) { return d < kDist0 ? kGammaC * (kDist0 - d) / std::max(d, 0.1 * kDist0) : 0.0; }

/// int_I P_c(dist) n over the circle's chords: the force on the body is minus this [N/m].
Vec2 penalty_integral(const std::vector<fsi::Segment2>& walls, const Vec2& centre, bool corners_as_walls) {
  const auto interface = circle(centre);
  const fsi::core::ContactDistance distance(walls, interface, centre, kDist0, kRadius, corners_as_walls);
  Vec2 sum(0.0, 0.0);
  for (const auto& seg : interface) {
    const Vec2 mid = 0.5 * (seg.a + seg.b);
    sum += pressure(distance(mid)) * (seg.b - seg.a).norm() * (mid - centre).normalized();
  }
  return sum;
}

/// The ball's centre at gap g from the corner, along the direction `angle` (radians from
/// the vertical, towards the riser's side).
Vec2 centre_off_corner(double gap, double angle) {
  return Vec2(3.2, 0.5) + (kRadius + gap) * Vec2(std::sin(angle), std::cos(angle));
}

TEST(ContactDistance, ACornerPushesLikeAFlatWallAtTheSameGap) {
  for (double gap : {2e-3, 5e-3}) {
    const double flat = penalty_integral(floor_wall(), Vec2(3.0, 0.5 + kRadius + gap), true).norm();
    for (double angle : {0.3, 0.7, 1.2}) {  // rolling over the edge, half way, beside the riser
      const Vec2 centre = centre_off_corner(gap, angle);
      const Vec2 corner = penalty_integral(stair(), centre, true);
      const Vec2 point = penalty_integral(stair(), centre, false);
      EXPECT_NEAR(corner.norm(), flat, 0.05 * flat) << "gap " << gap << ", angle " << angle;
      // Along the line from the corner to the centre: it pushes the ball straight away.
      const Vec2 away = (centre - Vec2(3.2, 0.5)).normalized();
      EXPECT_GT(-corner.dot(away), 0.99 * corner.norm());
      // The chapter's distance to the corner point: a fraction of the flat wall's force.
      EXPECT_LT(point.norm(), 0.3 * flat) << "gap " << gap << ", angle " << angle;
    }
  }
}

TEST(ContactDistance, FlatWallsAndCornersOutOfReachKeepThePlainDistance) {
  const std::vector<fsi::Segment2> walls = stair();
  // Resting on the tread 5 cm from its edge: the corner is 1.3 cm away, out of reach.
  const Vec2 on_tread(3.15 - 0.05, 0.5 + kRadius + 2e-3);
  const auto interface = circle(on_tread);
  const fsi::core::ContactDistance distance(walls, interface, on_tread, kDist0, kRadius, true);
  EXPECT_EQ(distance.num_corner_walls(), 0);
  for (const auto& seg : interface)
    EXPECT_EQ(distance(seg.a), fsi::mesh::distance_to_walls(walls, seg.a).distance_m);
}

TEST(ContactDistance, OnlyShortensDistancesAndOnlyNearTheCorner) {
  const std::vector<fsi::Segment2> walls = stair();
  const Vec2 centre = centre_off_corner(3e-3, 0.7);
  const auto interface = circle(centre);
  const fsi::core::ContactDistance distance(walls, interface, centre, kDist0, kRadius, true);
  EXPECT_EQ(distance.num_corner_walls(), 1);
  for (const auto& seg : interface) {
    const double plain = fsi::mesh::distance_to_walls(walls, seg.a).distance_m;
    EXPECT_LE(distance(seg.a), plain);
    EXPECT_GE(distance(seg.a), 3e-3 - 1e-6) << "no body point is nearer than the gap";
    if ((seg.a - Vec2(3.2, 0.5)).norm() > kRadius) {
      EXPECT_EQ(distance(seg.a), plain);
    }
  }
  // Off: the chapter's distance everywhere.
  const fsi::core::ContactDistance chapter(walls, interface, centre, kDist0, kRadius, false);
  EXPECT_EQ(chapter.num_corner_walls(), 0);
  for (const auto& seg : interface) EXPECT_EQ(chapter(seg.a), fsi::mesh::distance_to_walls(walls, seg.a).distance_m);
}

}  // namespace
