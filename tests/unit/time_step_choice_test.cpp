// The length of the next step (core/time_step_choice.hpp): k near the walls, k 2^j up to
// k 2^time_step_max_doublings where the body needs at least four such steps to reach the wall zone.
#include "core/time_step_choice.hpp"

#include "fe/cut_mesh.hpp"
#include "mesh/patch_mesh.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace {

using fsi::core::choose_time_step;

constexpr double kWide = 1.0;  // patches of 1 m: the patch criterion never binds

/// The chapter's numerics with steps up to k 2^doublings away from the walls (k = 1e-3 s).
fsi::NumericsSpec numerics(int doublings) {
  fsi::NumericsSpec n = fsi::numerics_for(fsi::Method::chapter);
  n.time_step_s = 1e-3;
  n.time_step_max_doublings = doublings;
  n.time_step_wall_zone_m = 0.03;
  n.end_time_s = 12.0;
  return n;
}

fsi::Functionals body(double distance_m, double vx_mps, double vy_mps) {
  fsi::Functionals f;
  f.min_distance_m = distance_m;
  f.mean_vx_mps = vx_mps;
  f.mean_vy_mps = vy_mps;
  return f;
}

/// The unit square in `columns` equal patches across and the rows of `y`.
fsi::mesh::PatchMesh unit_box(int columns, const fsi::AxisPiece& y) {
  fsi::MeshSpec spec;
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{0.0, 1.0, columns, 0.0, 0.0}};
  b.y = {y};
  spec.blocks = {b};
  return fsi::mesh::build_patch_mesh(spec, {});
}

TEST(TimeStepChoice, OffInTheChaptersMethodEveryStepIsK) {
  // time_step_max_doublings = 0: the chapter's constant step
  const fsi::NumericsSpec n = fsi::numerics_for(fsi::Method::chapter);
  EXPECT_EQ(choose_time_step(n, body(1.0, 0.0, 0.0), kWide, 0.0), n.time_step_s);
}

TEST(TimeStepChoice, InsideTheWallZoneTheStepIsK) {
  const auto n = numerics(3);
  EXPECT_EQ(choose_time_step(n, body(0.029, 0.0, 0.0), kWide, 1.0), 1e-3);
  EXPECT_EQ(choose_time_step(n, body(0.03, 0.0, 0.0), kWide, 1.0), 1e-3);
  // No interface (a body gone): distance 0, the safe step.
  EXPECT_EQ(choose_time_step(n, body(0.0, 0.0, 0.0), kWide, 1.0), 1e-3);
}

TEST(TimeStepChoice, AtRestFarFromTheWallsTheLongestStep) {
  EXPECT_DOUBLE_EQ(choose_time_step(numerics(3), body(0.2, 0.0, 0.0), kWide, 0.0), 8e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(numerics(2), body(0.2, 0.0, 0.0), kWide, 0.0), 4e-3);
}

TEST(TimeStepChoice, ApproachingTheZoneTheStepComesDownToK) {
  const auto n = numerics(3);
  // 1 m/s: four steps of 8e-3 cover 3.2 cm, of 4e-3 1.6 cm, of 2e-3 8 mm.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.033, 0.0, -1.0), kWide, 0.0), 8e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.031, 0.0, -1.0), kWide, 0.0), 4e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.0161, 0.0, -1.0), kWide, 0.0), 4e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.0159, 0.0, -1.0), kWide, 0.0), 2e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.0079, 0.0, -1.0), kWide, 0.0), 1e-3);
  // The speed counts, not its direction: 0.6 m/s right and 0.8 down is 1 m/s.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.03 + 0.0159, 0.6, -0.8), kWide, 0.0), 2e-3);
}

TEST(TimeStepChoice, TheInterfaceCrossesAtMostAnEighthOfItsSmallestCutPatch) {
  const auto n = numerics(3);  // time_step_patch_fraction 1/8 by default
  // 0.5 m/s in rows of 21 mm: 0.125 x 21 mm / 0.5 m/s = 5.25e-3 s -> 4e-3.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, -0.5), 0.021, 0.0), 4e-3);
  // In the 4 mm rows the bound is 1e-3: k itself.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, -0.5), 0.004, 0.0), 1e-3);
  // In 6 cm patches 8e-3 moves it 4 mm: allowed.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, -0.5), 0.06, 0.0), 8e-3);
}

TEST(TimeStepChoice, NeverPastTheEndTime) {
  const auto n = numerics(3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 12.0 - 0.005), 4e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 12.0 - 0.0015), 1e-3);
}

TEST(TimeStepChoice, AtMostTheLimitTheLastStepsLeft) {
  const auto n = numerics(3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 1.0, 2e-3), 2e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 1.0, 3e-3), 2e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 1.0, 1e-3), 1e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 1.0, 16e-3), 8e-3);
  // A limit never takes the step below k (the chapter's step) nor past the other rules.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.5, 0.0, 0.0), kWide, 1.0, 1e-4), 1e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.029, 0.0, 0.0), kWide, 1.0, 8e-3), 1e-3);
}

TEST(TimeStepChoice, TheLimitDoublesAfterCalmStepsHalvesAfterLaboriousOnesAndIsKAfterTrouble) {
  using fsi::core::kCalmNewtonIterations;
  using fsi::core::next_time_step_limit;
  constexpr double k = 1e-3;
  EXPECT_DOUBLE_EQ(next_time_step_limit({k, true, 3}, k), 2e-3);
  EXPECT_DOUBLE_EQ(next_time_step_limit({4e-3, true, kCalmNewtonIterations}, k), 8e-3);
  EXPECT_DOUBLE_EQ(next_time_step_limit({8e-3, true, kCalmNewtonIterations + 1}, k), 4e-3);
  EXPECT_DOUBLE_EQ(next_time_step_limit({k, true, 20}, k), k);
  // Unconverged, flagged or halved: back to k, from any length.
  EXPECT_DOUBLE_EQ(next_time_step_limit({8e-3, false, 3}, k), k);
  EXPECT_DOUBLE_EQ(next_time_step_limit({k / 4, false, 30}, k), k);
  // From k the way back to 8e-3 takes three calm steps.
  double limit = k;
  for (int i = 0; i < 3; ++i) limit = next_time_step_limit({limit, true, 4}, k);
  EXPECT_DOUBLE_EQ(limit, 8e-3);
}

TEST(TimeStepChoice, InTheWallZoneLongerStepsOnlyForASlowBodyWhenAllowed) {
  auto n = numerics(3);
  // Off (time_step_wall_zone_doublings = 0): k in the zone whatever the speed.
  EXPECT_EQ(choose_time_step(n, body(0.006, 0.0, 0.0), kWide, 1.0), 1e-3);
  n.time_step_wall_zone_doublings = 2;  // up to 4e-3 s
  // At rest 6 mm from the wall: up to the zone's own longest step, not time_step_max_s().
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.006, 0.0, 0.0), 0.004, 1.0), 4e-3);
  // Slow, 0.02 m/s: four steps of 4e-3 s cover 0.32 mm; the interface moves 0.08 mm per
  // step, within 1/32 of a 4 mm row (0.125 mm).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.006, 0.02, 0.0), 0.004, 1.0), 4e-3);
  // Four steps must not reach the wall: 0.5 mm away, 2e-3 (0.16 mm in four).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.0002, 0.02, 0.0), kWide, 1.0), 2e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.00015, 0.02, 0.0), kWide, 1.0), 1e-3);
  // Rolling at 0.19 m/s (the rho_f = 1000 ball on tread 1) in 6 mm rows: k (2e-3 s would
  // move it 0.38 mm, more than 1/32 of the row, although 1/8 of it outside the zone).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.006, 0.19, 0.0), 0.006, 1.0), 1e-3);
  // Arriving at 0.5 m/s: k.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.006, 0.0, -0.5), 0.004, 1.0), 1e-3);
  // No interface (no patch is cut: infinite side): k.
  EXPECT_EQ(choose_time_step(n, body(0.0, 0.0, 0.0), std::numeric_limits<double>::infinity(), 1.0), 1e-3);
  // Real contact at rest: the zone's longest step, as far as the patch rule allows.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.0, 0.0, 0.0), 0.004, 1.0), 4e-3);
  // An interface through a wall node whose distance is 0 only up to rounding (Example 1
  // at rest: 1e-17 to 5e-17 m, 1e-6 m/s) touches the wall: 2k at most (kTouchingStepFactor);
  // a gap of a micrometre is a gap (four steps of 2e-3 s at 1 mm/s would cross it 8 times).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(2e-17, 0.0, -1e-6), 0.004, 1.0), 2e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(1e-6, 0.0, -1e-3), 0.004, 1.0), 1e-3);
  // Real contact at 0.02 m/s in 4 mm rows: 2e-3 s moves it 0.04 mm (1/100 of the row),
  // 4e-3 s 0.08 mm, within the 1/32 (0.125 mm); at 0.05 m/s 2e-3 s (0.1 mm).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.0, 0.02, 0.0), 0.004, 1.0), 4e-3);
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.0, 0.05, 0.0), 0.004, 1.0), 2e-3);
  // The controller's limit binds there too.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.006, 0.0, 0.0), kWide, 1.0, 2e-3), 2e-3);
  // Just outside the zone a slow body keeps the longer of the two rules.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.0301, 0.0, 0.0), kWide, 1.0), 8e-3);
}

TEST(TimeStepChoice, InTheWallZoneABodyAtTheTurnOfAnImpactTakesK) {
  using fsi::core::SolidMotion;
  auto n = numerics(3);
  n.time_step_wall_zone_doublings = 2;  // up to 4e-3 s
  // 2 mm up, rows of 4 mm, mean velocity zero. At rest: up to 4e-3 s.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.002, 0.0, 0.0), 0.004, 1.0, 0.0, SolidMotion{0.0, 0.0}), 4e-3);
  // At the turn of an impact (the stiff ball: nodes at 0.02 m/s, decelerating at 8 m/s^2,
  // 0.18 m/s within the look-ahead): k.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.002, 0.0, 0.0), 0.004, 1.0, 0.0, SolidMotion{0.02, 8.0}), 1e-3);
  // Its top still coming down at 0.3 m/s: k.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.002, 0.0, 0.0), 0.004, 1.0, 0.0, SolidMotion{0.3, 0.0}), 1e-3);
  // Settling: 0.005 m/s, 0.1 m/s^2 (0.007 m/s within the look-ahead; 4e-3 s steps move it
  // 0.03 mm, within 1/32 of the row): the longer steps stay.
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.002, 0.0, 0.0), 0.004, 1.0, 0.0, SolidMotion{0.005, 0.1}), 4e-3);
  // Outside the zone the mean velocity alone decides (a spinning ball in flight).
  EXPECT_DOUBLE_EQ(choose_time_step(n, body(0.2, 0.0, 0.0), kWide, 1.0, 0.0, SolidMotion{0.3, 8.0}), 8e-3);
  // A non-finite motion gives k.
  EXPECT_EQ(choose_time_step(n, body(0.002, 0.0, 0.0), 0.004, 1.0, 0.0,
                             SolidMotion{std::numeric_limits<double>::quiet_NaN(), 0.0}),
            1e-3);
}

TEST(TimeStepChoice, SolidMotionFromTheSolidNodesOfBothLevels) {
  const fsi::mesh::PatchMesh mesh = unit_box(4, fsi::AxisPiece{0.0, 1.0, 4, 0.0, 0.0});
  const auto below = [&](double y0) {
    return fsi::fe::build_cut_mesh(mesh,
                                   fsi::fe::cut_data(mesh, [=](const fsi::mesh::Vec2& x) { return x.y() - y0; }));
  };
  // The solid: y < 0.4 now, y < 0.45 a step of 0.01 s before.
  const fsi::fe::CutMesh cut = below(0.4), previous_cut = below(0.45);
  const int nodes = static_cast<int>(cut.touches_solid.size());
  Eigen::VectorXd now = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * nodes), before = now;
  int inside = -1, interface = -1;
  for (int i = 0; i < nodes; ++i) {
    const bool solid = cut.touches_solid[i];
    now[fsi::kFieldsPerNode * i + fsi::kVx] = solid ? 0.01 : 5.0;  // the fluid fast: not counted
    before[fsi::kFieldsPerNode * i + fsi::kVx] = solid ? 0.01 : -5.0;
    const bool inside_at_both =
        solid && !cut.touches_fluid[i] && previous_cut.touches_solid[i] && !previous_cut.touches_fluid[i];
    if (inside_at_both && inside < 0) inside = i;
    if (solid && cut.touches_fluid[i] && interface < 0) interface = i;
  }
  ASSERT_GE(inside, 0);
  ASSERT_GE(interface, 0);
  auto motion = fsi::core::solid_motion(cut, now, previous_cut, before, 0.01);
  EXPECT_DOUBLE_EQ(motion.max_speed_mps, 0.01);
  EXPECT_DOUBLE_EQ(motion.max_acceleration_mps2, 0.0);
  // One node inside at (0.3, -0.4) m/s, before at rest: 0.5 m/s, 50 m/s^2.
  now[fsi::kFieldsPerNode * inside + fsi::kVx] = 0.3;
  now[fsi::kFieldsPerNode * inside + fsi::kVy] = -0.4;
  before[fsi::kFieldsPerNode * inside + fsi::kVx] = 0.0;
  motion = fsi::core::solid_motion(cut, now, previous_cut, before, 0.01);
  EXPECT_DOUBLE_EQ(motion.max_speed_mps, 0.5);
  EXPECT_DOUBLE_EQ(motion.max_acceleration_mps2, 50.0);
  // A jump at an interface node counts in the speed, not in the acceleration.
  now[fsi::kFieldsPerNode * interface + fsi::kVx] = 0.8;
  motion = fsi::core::solid_motion(cut, now, previous_cut, before, 0.01);
  EXPECT_DOUBLE_EQ(motion.max_speed_mps, 0.8);
  EXPECT_DOUBLE_EQ(motion.max_acceleration_mps2, 50.0);
  // No step before (the first step): no acceleration.
  EXPECT_EQ(fsi::core::solid_motion(cut, now, previous_cut, before, 0.0).max_acceleration_mps2, 0.0);
  // No solid: nothing.
  const fsi::fe::CutMesh none = below(-1.0);
  EXPECT_EQ(fsi::core::solid_motion(none, now, none, before, 0.01).max_speed_mps, 0.0);
}

TEST(TimeStepChoice, NonFiniteFunctionalsGiveK) {
  const auto n = numerics(3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(choose_time_step(n, body(0.5, nan, 0.0), kWide, 0.0), 1e-3);
  EXPECT_EQ(choose_time_step(n, body(nan, 0.0, 0.0), kWide, 0.0), 1e-3);
}

TEST(TimeStepChoice, CutPatchSideIsTheSmallestPatchTheInterfaceCuts) {
  // A box graded in y: rows of 1 cm at y = 0 growing to 10 cm at the top, 10 cm wide.
  const fsi::mesh::PatchMesh mesh = unit_box(10, fsi::AxisPiece{0.0, 1.0, 20, 0.01, 0.1});
  double smallest = 1.0, cut_smallest = 1.0;
  const auto circle = [](double cy, double r) {
    return [=](const fsi::mesh::Vec2& x) { return std::hypot(x.x() - 0.5, x.y() - cy) - r; };
  };
  // A ball in the upper half cuts only the tall rows there: not the 1 cm rows below.
  const fsi::fe::CutMesh high = fsi::fe::build_cut_mesh(mesh, fsi::fe::cut_data(mesh, circle(0.75, 0.15)));
  for (int p = 0; p < mesh.num_patches(); ++p) {
    smallest = std::min(smallest, mesh.patches[p].min_size_m);
    if (high.kind[p] != fsi::fe::PatchKind::uncut) cut_smallest = std::min(cut_smallest, mesh.patches[p].min_size_m);
  }
  EXPECT_NEAR(smallest, 0.01, 1e-3);
  EXPECT_GT(cut_smallest, 0.04);
  EXPECT_DOUBLE_EQ(fsi::core::cut_patch_side(mesh, high), cut_smallest);
  // Its bottom 5 mm above y = 0 cuts the 1 cm row.
  const fsi::fe::CutMesh low = fsi::fe::build_cut_mesh(mesh, fsi::fe::cut_data(mesh, circle(0.155, 0.15)));
  EXPECT_NEAR(fsi::core::cut_patch_side(mesh, low), smallest, 1e-12);
  // No interface: no bound.
  const fsi::fe::CutMesh none = fsi::fe::build_cut_mesh(mesh, fsi::fe::cut_data(mesh, circle(0.5, 5.0)));
  EXPECT_TRUE(std::isinf(fsi::core::cut_patch_side(mesh, none)));
}

}  // namespace
