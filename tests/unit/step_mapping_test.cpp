// The IPS mapping (12.4) on prescribed linear deformations, where the answer is known:
// u^{m-1}(x) = A x, u^{m-2}(x) = B x  =>  x^{m-1} = (I - B)^{-1} (I - A) x^m.
#include "interface/step_mapping.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"
#include "test_scenarios.hpp"

namespace {

using fsi::mesh::Vec2;

Eigen::VectorXd linear_displacement(const fsi::fe::CutMesh& cut, const Eigen::Matrix2d& a,
                                    const Eigen::Vector2d& v_gradient_x) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(5 * cut.x.size());
  for (std::size_t n = 0; n < cut.x.size(); ++n) {
    const Eigen::Vector2d u = a * cut.x[n];
    s[5 * n + fsi::kUx] = u.x();
    s[5 * n + fsi::kUy] = u.y();
    s[5 * n + fsi::kVx] = v_gradient_x.dot(cut.x[n]);  // a linear velocity field to sample
  }
  return s;
}

TEST(StepMapping, SolvesTheInitialPointSetEquationForLinearDeformations) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  Eigen::Matrix2d a, b;
  a << 0.02, 0.01, -0.015, 0.03;
  b << 0.01, 0.0, 0.005, 0.012;
  const Eigen::Vector2d vgrad(0.3, -0.7);
  // Geometries: the mesh of u^{m-2}'s level and of u^{m-1}'s level (any cut will do:
  // linear functions are represented exactly on every cut mesh).
  auto ball = [&](const Eigen::Matrix2d& m) {
    return fsi::fe::build_cut_mesh(mesh, [&, m](const Vec2& x) {
      return fsi::interface::initial_distance(s.body, x - m * x);
    });
  };
  const fsi::fe::CutMesh prev = ball(Eigen::Matrix2d::Zero()), cur = ball(b), next = ball(a);
  const Eigen::VectorXd s_prev = linear_displacement(prev, b, vgrad);
  const Eigen::VectorXd s_cur = linear_displacement(cur, a, vgrad);
  const auto quad = fsi::fe::build_quadrature(next);
  fsi::interface::MappingOptions mo;
  mo.k_s = 0.01;
  std::vector<fsi::forms::OldValues> old;
  const auto stats = fsi::interface::compute_old_values(mesh, buckets, next, quad, {&cur, &s_cur},
                                                        {&prev, &s_prev}, fsi::scene_bodies(s), s.walls, mo, old);
  EXPECT_GT(stats.ips_points, 100);
  EXPECT_EQ(stats.ips_failures, 0);
  const Eigen::Matrix2d map = (Eigen::Matrix2d::Identity() - b).inverse() * (Eigen::Matrix2d::Identity() - a);
  int exact_points = 0;
  for (std::size_t q = 0; q < quad.points.size(); ++q) {
    const Vec2 x = quad.points[q].x;
    const Vec2 y = map * x;                         // x^{m-1} from (12.4)
    const Vec2 dt(old[q].tx, old[q].ty);            // g (x - y) / k with g in [0, 1]
    const Vec2 full = (x - y) / mo.k_s;
    const double g = full.squaredNorm() > 0 ? dt.dot(full) / full.squaredNorm() : 0.0;
    ASSERT_GE(g, -1e-9);
    ASSERT_LE(g, 1.0 + 1e-9);
    EXPECT_LT((dt - g * full).norm(), 1e-7 * (1.0 + full.norm()));
    // Old values are sampled at T(x) = x - k d_t T.
    const Vec2 t = x - mo.k_s * dt;
    EXPECT_NEAR(old[q].vx, vgrad.dot(t), 1e-9);
    const Vec2 u_at_t = a * t;
    EXPECT_NEAR(old[q].ux, u_at_t.x(), 1e-9);
    if (std::abs(fsi::interface::initial_distance(s.body, x - a * x)) < 0.01) {
      EXPECT_NEAR(g, 1.0, 1e-9) << "at the interface T follows the IPS map exactly";
      ++exact_points;
    }
  }
  EXPECT_GT(exact_points, 20);
}

}  // namespace
