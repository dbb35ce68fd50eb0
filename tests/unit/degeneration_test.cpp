// The checks that keep a broken body out of a run (core/degeneration.hpp), on constructed
// functionals: each cause is found and named with its place, and the motions of a sound
// run (a fall, an impact's turn, a body at rest) pass.
#include "core/degeneration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fe/cut_mesh.hpp"
#include "fsi/scenario.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"

namespace {

using fsi::core::detect_degeneration;

/// Example 1's ball, radius 0.2 m, centred at (0, y), falling at vy.
fsi::Functionals ball(double y, double vy, double mass_error = 1e-3) {
  fsi::Functionals f;
  f.centroid_x_m = 0.0;
  f.centroid_y_m = y;
  f.bottom_y_m = y - 0.2;
  f.top_y_m = y + 0.2;
  f.left_x_m = -0.2;
  f.right_x_m = 0.2;
  f.mean_vy_mps = vy;
  f.mass_error = mass_error;
  return f;
}

constexpr double kStep = 2e-3, kPatch = 0.0625;

TEST(Degeneration, SoundMotionsPass) {
  // A fall at 0.5 m/s over one step, a turn at the ground, a body at rest with the
  // interface shifted by a patch side (a cut snapping to another node).
  EXPECT_FALSE(detect_degeneration(ball(0.0, -0.5), ball(-0.001, -0.5), kStep, kPatch, 0, {}));
  EXPECT_FALSE(detect_degeneration(ball(-0.79, -0.01), ball(-0.79, 0.01), kStep, kPatch, 0, {}));
  EXPECT_FALSE(detect_degeneration(ball(-0.79, 0.0), ball(-0.79 + kPatch, 0.0), kStep, kPatch, 0, {}));
  EXPECT_FALSE(detect_degeneration(ball(-0.79, 0.0, 0.004), ball(-0.79, 0.0, 0.02), kStep, kPatch, 0, {}));
}

TEST(Degeneration, AnInvertedSolidIsNamedWithItsPlace) {
  const auto d = detect_degeneration(ball(0.0, -0.5), ball(-0.001, -0.5), kStep, kPatch, 3, {0.1, -0.2});
  ASSERT_TRUE(d);
  EXPECT_NE(d->cause.find("inside out at 3 quadrature point(s)"), std::string::npos) << d->cause;
  EXPECT_DOUBLE_EQ(d->where_m.x, 0.1);
  EXPECT_DOUBLE_EQ(d->where_m.y, -0.2);
}

TEST(Degeneration, AJumpOfTheMassErrorIsFound) {
  const auto d = detect_degeneration(ball(-0.79, 0.0, 0.01), ball(-0.79, 0.0, 0.04), kStep, kPatch, 0, {});
  ASSERT_TRUE(d);
  EXPECT_NE(d->cause.find("mass error jumped from 0.01 to 0.04"), std::string::npos) << d->cause;
  EXPECT_DOUBLE_EQ(d->where_m.y, -0.79);  // the body's centroid
}

TEST(Degeneration, ASmallBodyInLargePatchesMayChangeItsMassErrorByOnePatch) {
  // A ball of R = 0.1 m among 5 cm patches: one patch's cut rebuilt changes the discrete
  // area by up to 0.0025 m^2 of its 0.0314 m^2 (0.08). A campaign ball of R = 0.104 m went
  // from 0.057 to 0.080 in one converged step; more than a patch is still a broken body.
  fsi::Functionals before = ball(-0.5, -0.5, 0.057), after = ball(-0.501, -0.5, 0.080);
  before.solid_area_m2 = after.solid_area_m2 = M_PI * 0.1 * 0.1;
  constexpr double kPatchArea = 0.05 * 0.05;
  EXPECT_FALSE(detect_degeneration(before, after, kStep, 0.05, 0, {}, kPatchArea));
  after.mass_error = 0.2;
  const auto d = detect_degeneration(before, after, kStep, 0.05, 0, {}, kPatchArea);
  ASSERT_TRUE(d);
  EXPECT_NE(d->cause.find("jumped from 0.057 to 0.2 in one step (more than 0.08)"), std::string::npos) << d->cause;
  // Without the patch's area the bound is the fixed one.
  after.mass_error = 0.080;
  EXPECT_TRUE(detect_degeneration(before, after, kStep, 0.05, 0, {}));
}

TEST(Degeneration, AnInterfaceThatJumpsFurtherThanTheBodyMovesIsFound) {
  fsi::Functionals after = ball(-0.79, 0.0);
  after.bottom_y_m -= 3.0 * kPatch;  // the rim pulled through the floor in one step
  const auto d = detect_degeneration(ball(-0.79, 0.0), after, kStep, kPatch, 0, {});
  ASSERT_TRUE(d);
  EXPECT_NE(d->cause.find("interface jumped by 0.188 m"), std::string::npos) << d->cause;
  // The same distance at a speed that covers it is motion, not a jump.
  EXPECT_FALSE(detect_degeneration(ball(-0.79, -50.0), after, kStep, kPatch, 0, {}));
}

TEST(Degeneration, NonFiniteFunctionalsAreABrokenBody) {
  fsi::Functionals after = ball(-0.79, 0.0);
  after.mass_error = std::numeric_limits<double>::quiet_NaN();
  const auto d = detect_degeneration(ball(-0.79, 0.0), after, kStep, kPatch, 0, {});
  ASSERT_TRUE(d);
  EXPECT_NE(d->cause.find("not finite"), std::string::npos) << d->cause;
}

TEST(Degeneration, ABodyAtTheOpenBoundaryIsNamedWithItsPlace) {
  // Example 1's domain: a floor (a wall), open sides and top.
  const fsi::Scenario s = fsi::example1_scenario();
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const auto at_open_boundary = [&](double x, double y, double r) {
    fsi::BodySpec b;
    b.center_m = {x, y};
    b.radius_m = r;
    const fsi::BodySpec bodies[] = {b};
    const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(
        mesh, [&](const Eigen::Vector2d& p) { return fsi::interface::scene_distance(bodies, p); });
    return fsi::core::body_at_open_boundary(mesh, cut);
  };
  EXPECT_FALSE(at_open_boundary(0.0, 0.0, 0.4));           // Example 1's ball
  EXPECT_FALSE(at_open_boundary(0.0, -1.0 + 0.39, 0.4));   // pressed 1 cm into the floor: a wall
  const auto left = at_open_boundary(-0.65, -0.3, 0.4);    // 5 cm past the open left side
  ASSERT_TRUE(left.has_value());
  EXPECT_DOUBLE_EQ(left->where_m.x, -1.0);
  EXPECT_NEAR(left->where_m.y, -0.3, 0.195);  // on the chord the ball cuts off x = -1
  EXPECT_NE(left->cause.find("reached the open boundary"), std::string::npos) << left->cause;
  const auto top = at_open_boundary(0.3, 0.2, 0.4);        // 10 cm through the open top
  ASSERT_TRUE(top.has_value());
  EXPECT_DOUBLE_EQ(top->where_m.y, 0.5);
}

}  // namespace

