// Re-referencing the body (core/rereference.hpp): the rigid motion leaves u, the
// level set d0(x - u) does not change, and the map is the least-squares rigid fit.
#include "core/rereference.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "test_scenarios.hpp"

namespace {

using fsi::mesh::Vec2;

TEST(Rereference, TakesTheRigidMotionOutOfUAndKeepsTheLevelSet) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) {
    return fsi::interface::initial_distance(s.body, x);
  });
  // The body turned by 0.7 rad about a point and moved (X = Q^T (x - t)), plus a small
  // elastic part; in the fluid some other extension.
  const double angle = 0.7, c = std::cos(angle), sn = std::sin(angle);
  const Vec2 t(0.25, -0.1);
  auto initial_point = [&](const Vec2& x) {
    const Vec2 d = x - t;
    return Vec2(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());
  };
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2& x = cut.x[n];
    const Vec2 elastic(1e-4 * std::sin(7.0 * x.y()), 1e-4 * std::cos(5.0 * x.x()));
    const Vec2 u = cut.touches_solid[n] ? Vec2(x - initial_point(x) + elastic) : Vec2(0.3 * x + Vec2(0.1, 0.0));
    solution.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2) = u;
  }
  const fsi::core::RigidFit fit = fsi::core::fit_rigid_motion(cut, solution);
  ASSERT_GT(fit.nodes, 20);
  EXPECT_NEAR(fit.angle_rad, angle, 1e-3);

  Eigen::VectorXd moved = solution;
  fsi::core::rereference_displacement(cut, fit, moved);
  fsi::BodySpec body = s.body;
  const Vec2 centre = fsi::core::rereferenced_point(fit, {s.body.center_m.x, s.body.center_m.y});
  body.center_m = {centre.x(), centre.y()};
  double largest_solid_u = 0.0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2 u = solution.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2);
    const Vec2 u_new = moved.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2);
    // The level set, hence the interface, is the same at every node, solid or fluid.
    EXPECT_NEAR(fsi::interface::initial_distance(body, cut.x[n] - u_new),
                fsi::interface::initial_distance(s.body, cut.x[n] - u), 1e-12)
        << "node " << n;
    if (cut.touches_solid[n] && !cut.touches_fluid[n]) largest_solid_u = std::max(largest_solid_u, u_new.norm());
    // Velocities and pressure are untouched.
    EXPECT_EQ(moved[fsi::kFieldsPerNode * n + fsi::kVx], solution[fsi::kFieldsPerNode * n + fsi::kVx]);
    EXPECT_EQ(moved[fsi::kFieldsPerNode * n + fsi::kP], solution[fsi::kFieldsPerNode * n + fsi::kP]);
  }
  // What stays in the solid is the elastic part (1e-4 m) and the fit's error, not the
  // motion (0.7 rad on a 0.25 m ball: u up to 0.4 m before).
  EXPECT_LT(largest_solid_u, 5e-4);
}

TEST(Rereference, KeepsTheLevelSetOfAnEllipseTurnedWithIt) {
  // An ellipse's d0 sees the rotation: the re-referenced body is turned by the fit's angle
  // (Engine's reference_body adds State::reference_rotation_rad to angle_rad).
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.body.shape = fsi::BodyShape::ellipse;
  s.body.half_size_m = {0.45, 0.25};
  s.body.angle_rad = 0.2;
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) {
    return fsi::interface::initial_distance(s.body, x);
  });
  const double angle = -0.9, c = std::cos(angle), sn = std::sin(angle);
  const Vec2 t(-0.2, -0.15);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2 d = cut.x[n] - t;
    const Vec2 X(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());  // Q^T (x - t)
    solution.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2) = cut.x[n] - X;
  }
  const fsi::core::RigidFit fit = fsi::core::fit_rigid_motion(cut, solution);
  ASSERT_GT(fit.nodes, 20);
  EXPECT_NEAR(fit.angle_rad, angle, 1e-9);
  Eigen::VectorXd moved = solution;
  fsi::core::rereference_displacement(cut, fit, moved);
  fsi::BodySpec body = s.body;
  const Vec2 centre = fsi::core::rereferenced_point(fit, {s.body.center_m.x, s.body.center_m.y});
  body.center_m = {centre.x(), centre.y()};
  body.angle_rad += fit.angle_rad;
  fsi::BodySpec unturned = body;
  unturned.angle_rad = s.body.angle_rad;
  int differ = 0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2 u = solution.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2);
    const Vec2 u_new = moved.segment(fsi::kFieldsPerNode * n + fsi::kUx, 2);
    const double before = fsi::interface::initial_distance(s.body, cut.x[n] - u);
    EXPECT_NEAR(fsi::interface::initial_distance(body, cut.x[n] - u_new), before, 1e-12) << "node " << n;
    if (std::abs(fsi::interface::initial_distance(unturned, cut.x[n] - u_new) - before) > 1e-3) ++differ;
  }
  EXPECT_GT(differ, mesh.num_nodes() / 2) << "without the turn the level set would move";
}

TEST(Rereference, NoSolidNodesGiveNoFit) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(mesh, [](const Vec2&) { return 1.0; });
  const Eigen::VectorXd solution = Eigen::VectorXd::Ones(fsi::kFieldsPerNode * mesh.num_nodes());
  EXPECT_EQ(fsi::core::fit_rigid_motion(cut, solution).nodes, 0);
}

}  // namespace
