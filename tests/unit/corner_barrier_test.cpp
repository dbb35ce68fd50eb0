// Convex wall corners keep bodies off (core/corner_barrier.hpp): which wall points are
// convex corners as a body sees them, and a barrier strong enough to stop a body at its
// design speed before the body reaches the corner.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/corner_barrier.hpp"

namespace {

using Vec2 = Eigen::Vector2d;

/// A stair: tread y = 0.5 for x <= 3.2, riser x = 3.2 down to the floor y = 0 (the
/// convex corner (3.2, 0.5), the concave one (3.2, 0)).
std::vector<fsi::Segment2> stair() {
  return {{{2.2, 0.5}, {3.2, 0.5}}, {{3.2, 0.5}, {3.2, 0.0}}, {{3.2, 0.0}, {4.4, 0.0}}};
}

/// The circle of radius r about `centre` as 2000 interface chords.
std::vector<fsi::fe::InterfaceSegment> circle(const Vec2& centre, double r) {
  std::vector<fsi::fe::InterfaceSegment> segments;
  constexpr int kChords = 2000;
  for (int i = 0; i < kChords; ++i) {
    const double a0 = 2.0 * std::numbers::pi * i / kChords, a1 = 2.0 * std::numbers::pi * (i + 1) / kChords;
    segments.push_back({centre + r * Vec2(std::cos(a0), std::sin(a0)), centre + r * Vec2(std::cos(a1), std::sin(a1))});
  }
  return segments;
}

TEST(CornerBarrier, OnlyTheTreadEdgeIsAConvexCorner) {
  // Seen from a ball over the lower floor beside the riser, and from one over the tread.
  for (const Vec2& centre : {Vec2(3.6, 0.4), Vec2(2.9, 0.9)}) {
    const auto corners = fsi::core::convex_corners(stair(), centre);
    ASSERT_EQ(corners.size(), 1u);
    EXPECT_NEAR((corners[0] - Vec2(3.2, 0.5)).norm(), 0.0, 1e-15);
  }
  // A box's inner corners and two collinear walls are none.
  const std::vector<fsi::Segment2> box = {{{-1, 1}, {-1, -1}}, {{-1, -1}, {1, -1}}, {{1, -1}, {1, 1}}};
  EXPECT_TRUE(fsi::core::convex_corners(box, Vec2(0.0, 0.0)).empty());
  const std::vector<fsi::Segment2> straight = {{{-1, -1}, {0, -1}}, {{0, -1}, {1, -1}}};
  EXPECT_TRUE(fsi::core::convex_corners(straight, Vec2(0.0, 0.0)).empty());
}

TEST(CornerBarrier, StoresTwiceTheKineticEnergyAtTheDesignSpeedBeforeTheCorner) {
  constexpr double kRadius = 0.3, kReach = 1e-2, kMass = 250.0, kSpeed = 1.0;
  const double gamma = fsi::core::CornerBarrier::gamma_for(kMass, kSpeed, kRadius, kReach);
  // A ball approaching the edge along the diagonal; the work of the barrier's force
  // along the way from d = reach to d = 0, by the midpoint rule over the gap.
  const Vec2 corner(3.2, 0.5), along = Vec2(1.0, 1.0).normalized();
  constexpr int kGaps = 200;
  double work = 0.0;
  for (int i = 0; i < kGaps; ++i) {
    const double gap = (i + 0.5) * kReach / kGaps;
    const Vec2 centre = corner + (kRadius + gap) * along;
    const auto interface = circle(centre, kRadius);
    const fsi::core::CornerBarrier barrier(stair(), interface, centre, kReach, kRadius, gamma, 0.1);
    ASSERT_EQ(barrier.num_corners(), 1);
    Vec2 force(0.0, 0.0);  // on the body: -P n_s
    for (const auto& seg : interface) {
      const Vec2 mid = 0.5 * (seg.a + seg.b);
      force -= barrier.pressure_pa(mid) * (seg.b - seg.a).norm() * (mid - centre).normalized();
    }
    EXPECT_GT(force.dot(along), 0.99 * force.norm()) << "pushes straight away from the corner";
    work += force.dot(along) * kReach / kGaps;
  }
  EXPECT_NEAR(work, kMass * kSpeed * kSpeed, 0.03 * kMass * kSpeed * kSpeed);
}

TEST(CornerBarrier, NothingBeyondItsReachNorWithoutStrength) {
  const Vec2 centre = Vec2(3.2, 0.5) + (0.3 + 0.02) * Vec2(1.0, 1.0).normalized();
  const auto interface = circle(centre, 0.3);
  EXPECT_EQ(fsi::core::CornerBarrier(stair(), interface, centre, 1e-2, 0.3, 1e5, 0.1).num_corners(), 0);
  const Vec2 near = Vec2(3.2, 0.5) + (0.3 + 0.005) * Vec2(1.0, 1.0).normalized();
  const auto close = circle(near, 0.3);
  EXPECT_EQ(fsi::core::CornerBarrier(stair(), close, near, 1e-2, 0.3, 1e5, 0.1).num_corners(), 1);
  EXPECT_EQ(fsi::core::CornerBarrier(stair(), close, near, 1e-2, 0.3, 0.0, 0.1).num_corners(), 0);
}

TEST(CornerBarrier, ABodyTooSoftForItsBarrierGetsALongerReach) {
  using fsi::core::CornerBarrier;
  // Campaign seed 5, case 24: R = 0.3052 m, rho_s = 2255 kg/m^3, mu_s = 6.902e4 Pa.
  const double radius = 0.3052, mass = 2255.0 * std::numbers::pi * radius * radius, mu = 6.902e4;
  EXPECT_NEAR(CornerBarrier::gamma_for(mass, 1.0, radius, 1e-2), 4.59e5, 0.01e5);
  const double reach = CornerBarrier::reach_for(mass, 1.0, radius, 1e-2, mu);
  EXPECT_NEAR(reach, 0.0354, 0.0005);
  EXPECT_NEAR(CornerBarrier::gamma_for(mass, 1.0, radius, reach), mu, 1e-6 * mu);
  // Twice the kinetic energy either way: the same work over the longer approach.
  EXPECT_NEAR(1.84 * reach * std::sqrt(2.0 * radius * reach) * CornerBarrier::gamma_for(mass, 1.0, radius, reach),
              mass, 1e-9 * mass);
  // A stiff ball (mu_s = 3.2e6 Pa) keeps the shortest reach; Example 1's ball (gamma 3.05e5
  // N/m within 1 cm, mu_s = 2e5 Pa) gets 1.3 cm.
  EXPECT_EQ(CornerBarrier::reach_for(mass, 1.0, radius, 1e-2, 3.2e6), 1e-2);
  EXPECT_NEAR(CornerBarrier::reach_for(1000.0 * std::numbers::pi * 0.16, 1.0, 0.4, 1e-2, 2e5), 0.0133, 0.0001);
  EXPECT_EQ(CornerBarrier::reach_for(mass, 1.0, radius, 1e-2, 0.0), 1e-2);  // no modulus: no change
}

}  // namespace
