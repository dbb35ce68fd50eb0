// The fluid's initial velocity around a ball that starts moving (interface::
// initial_fluid_velocity): the potential flow of a moving circle, divergence-free, with
// the ball's normal velocity at its surface, at rest far away and without motion.
#include "interface/body.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using fsi::interface::Vec2;

fsi::BodySpec thrown_ball() {
  fsi::BodySpec b;
  b.center_m = {0.1, -0.3};
  b.radius_m = 0.3;
  b.initial_velocity_mps = {1.0, -0.4};
  return b;
}

TEST(InitialFlow, MatchesTheBallsNormalVelocityAtItsSurface) {
  const fsi::BodySpec b = thrown_ball();
  const Vec2 c(b.center_m.x, b.center_m.y), u(b.initial_velocity_mps.x, b.initial_velocity_mps.y);
  for (int i = 0; i < 16; ++i) {
    const double a = 2.0 * M_PI * i / 16.0;
    const Vec2 n(std::cos(a), std::sin(a));
    const Vec2 v = fsi::interface::initial_fluid_velocity(b, c + b.radius_m * n);
    EXPECT_NEAR(v.dot(n), u.dot(n), 1e-12) << "angle " << a;
  }
}

TEST(InitialFlow, IsDivergenceFreeAndDecays) {
  const fsi::BodySpec b = thrown_ball();
  const double h = 1e-5;
  const auto v = [&b](const Vec2& p) { return fsi::interface::initial_fluid_velocity(b, p); };
  for (const Vec2& x : {Vec2(0.7, -0.3), Vec2(0.1, 0.2), Vec2(-0.5, -0.9), Vec2(0.45, 0.05)}) {
    const double div = (v(x + Vec2(h, 0)).x() - v(x - Vec2(h, 0)).x()) / (2 * h) +
                       (v(x + Vec2(0, h)).y() - v(x - Vec2(0, h)).y()) / (2 * h);
    EXPECT_NEAR(div, 0.0, 1e-8) << x.transpose();
  }
  // |v| = (R/r)^2 |U|: a quarter of the ball's speed one radius off its surface.
  EXPECT_NEAR(v(Vec2(0.1 + 0.6, -0.3)).norm(), 0.25 * std::hypot(1.0, 0.4), 1e-12);
}

TEST(InitialFlow, IsZeroForABallAtRest) {
  fsi::BodySpec b = thrown_ball();
  b.initial_velocity_mps = {0.0, 0.0};
  EXPECT_EQ(fsi::interface::initial_fluid_velocity(b, Vec2(0.7, -0.3)).norm(), 0.0);
}

}  // namespace
