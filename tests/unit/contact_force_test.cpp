// The penalty contact force of Sect. 12.5 as assembled into the residual: zero beyond
// dist_0, and near the ground it equals int_I P_c n_s (P_c = gamma_c (dist_0 - d)/d) and
// pushes the ball away from the wall; bounded where the ball really touches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/fsi_system.hpp"
#include "fe/cut_mesh.hpp"
#include "fe/element.hpp"
#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"
#include "test_scenarios.hpp"

namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kGammaC = 1600.0, kDist0 = 1e-2;

/// The coarse Example 1 with the ball's bottom `gap_m` above the ground (y = -1).
fsi::Scenario ball_above_ground(double gap_m, double gamma_c) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.body.center_m = {0.03, -1.0 + s.body.radius_m + gap_m};  // off the mesh's symmetry line
  s.contact = {gamma_c, kDist0};
  return s;
}

/// The contact part of the residual at x = 0, and the cut mesh it was assembled on.
struct ContactResidual {
  Eigen::VectorXd force;
  fsi::fe::CutMesh cut;
  double max_pressure_pa = 0.0;
};

ContactResidual contact_residual(double gap_m) {
  const fsi::Scenario with = ball_above_ground(gap_m, kGammaC);
  const fsi::Scenario without = ball_above_ground(gap_m, 0.0);
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(with.mesh, with.walls);
  ContactResidual result;
  result.cut = fsi::fe::build_cut_mesh(
      mesh, [&](const Vec2& x) { return fsi::interface::initial_distance(with.body, x); });
  const fsi::fe::QuadratureTable quadrature = fsi::fe::build_quadrature(result.cut);
  Eigen::VectorXd r_with, r_without;
  for (const auto* s : {&with, &without}) {
    fsi::core::FsiSystem system(*s, mesh);
    system.set_geometry(result.cut, quadrature, s->numerics.time_step_s);
    system.set_old_values(std::vector<fsi::forms::OldValues>(quadrature.points.size()));
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(system.size());
    system.residual(x, s == &with ? r_with : r_without);
    if (s == &with) result.max_pressure_pa = system.max_contact_pressure();
  }
  result.force = r_with - r_without;
  return result;
}

/// Sum of the (vx, vy) rows of a residual vector.
Vec2 row_sum(const Eigen::VectorXd& r) {
  Vec2 sum(0.0, 0.0);
  for (Eigen::Index n = 0; n < r.size() / fsi::kFieldsPerNode; ++n)
    sum += Vec2(r[fsi::kFieldsPerNode * n + fsi::kVx], r[fsi::kFieldsPerNode * n + fsi::kVy]);
  return sum;
}

double pressure(double d) { return d < kDist0 ? kGammaC * (kDist0 - d) / d : 0.0; }

TEST(ContactForce, ZeroFartherThanDist0FromEveryWall) {
  const ContactResidual c = contact_residual(2.0 * kDist0);
  EXPECT_EQ(c.force.lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_EQ(c.max_pressure_pa, 0.0);
}

TEST(ContactForce, EqualsTheIntegralOfPcNormalAndPushesAway) {
  const double gap = 4e-3;
  const ContactResidual c = contact_residual(gap);
  const fsi::Scenario s = ball_above_ground(gap, kGammaC);
  const Vec2 center(s.body.center_m.x, s.body.center_m.y);

  // Only momentum rows of nodes on the interface carry it.
  for (Eigen::Index i = 0; i < c.force.size(); ++i) {
    const int field = static_cast<int>(i % fsi::kFieldsPerNode);
    if (field != fsi::kVx && field != fsi::kVy) {
      EXPECT_EQ(c.force[i], 0.0) << "row " << i;
    }
  }

  // Independent integral over the same discrete interface, 200 midpoints per segment,
  // with the outer normal taken from the ball's centre.
  Vec2 discrete(0.0, 0.0);
  for (const auto& seg : c.cut.interface) {
    const Vec2 d = seg.b - seg.a;
    Vec2 n(d.y(), -d.x());
    n.normalize();
    if (n.dot(0.5 * (seg.a + seg.b) - center) < 0.0) n = -n;
    for (int q = 0; q < 200; ++q) {
      const Vec2 x = seg.a + (q + 0.5) / 200.0 * d;
      discrete += pressure(x.y() + 1.0) * d.norm() / 200.0 * n;
    }
  }
  // And over the exact circle (the discrete interface is its polygonal approximation).
  Vec2 circle(0.0, 0.0);
  const double r = s.body.radius_m;
  constexpr int kSteps = 200000;
  for (int i = 0; i < kSteps; ++i) {
    const double a = 2.0 * std::numbers::pi * (i + 0.5) / kSteps;
    const Vec2 n(std::cos(a), std::sin(a));
    circle += pressure(center.y() + r * n.y() + 1.0) * r * 2.0 * std::numbers::pi / kSteps * n;
  }

  const Vec2 assembled = row_sum(c.force);
  ASSERT_LT(discrete.y(), 0.0) << "n_s points into the ground at the ball's bottom";
  // Residual + int P_c n_s . phi: the force on the solid is -assembled, i.e. upwards.
  EXPECT_LT(assembled.y(), 0.0);
  EXPECT_NEAR(assembled.y(), discrete.y(), 0.01 * std::abs(discrete.y()));
  EXPECT_NEAR(assembled.x(), discrete.x(), 0.01 * std::abs(discrete.y()));
  EXPECT_NEAR(assembled.y(), circle.y(), 0.3 * std::abs(circle.y()));
  EXPECT_LT(std::abs(assembled.x()), 0.05 * std::abs(assembled.y())) << "no sideways push from flat ground";
  // The largest pressure is that of the lowest quadrature point: a little above the gap.
  EXPECT_LE(c.max_pressure_pa, pressure(0.8 * gap));
  EXPECT_GE(c.max_pressure_pa, pressure(1.5 * gap));
}

TEST(ContactForce, GrowsAsTheGapCloses) {
  const double far = -row_sum(contact_residual(8e-3).force).y();
  const double near = -row_sum(contact_residual(3e-3).force).y();
  EXPECT_GT(far, 0.0);
  EXPECT_GT(near, 2.0 * far);
}

TEST(ContactForce, BoundedWhereTheBodyReallyTouches) {
  // The ball reaches 0.5 mm below the ground line: the interface ends on the wall, where
  // the chapter's P_c is infinite. With dist >= min_dist_fraction * dist_0 (0.1) the
  // pressure stays between 9 and 10 gamma_c there, and still pushes the ball up.
  const ContactResidual c = contact_residual(-5e-4);
  EXPECT_LE(c.max_pressure_pa, 10.0 * kGammaC);
  EXPECT_GE(c.max_pressure_pa, 9.0 * kGammaC);
  EXPECT_TRUE(c.force.allFinite());
  EXPECT_LT(row_sum(c.force).y(), 0.0);
}

}  // namespace
