// Newton's start on the new mesh (core/initial_guess.hpp). The rule: where
// the interpolated start deforms a solid sub-element beyond any physical state, its nodes
// that lay in the fluid take v and u from the solid field, not from the fluid's
// extension (near a thin solid sub-element that had made det(I - grad u) <= 0), from the
// solid sub-element of their patch or, where it has none yet, of the patch beside it.
#include "core/initial_guess.hpp"

#include <gtest/gtest.h>

#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"
#include "test_scenarios.hpp"

namespace {

using fsi::mesh::Vec2;

/// The cut mesh of the scenario's body moved by `shift` [m].
fsi::fe::CutMesh body_moved_by(const fsi::Scenario& s, const fsi::mesh::PatchMesh& mesh, const Vec2& shift) {
  return fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) { return fsi::interface::initial_distance(s.body, x - shift); });
}

TEST(InitialGuess, NewlySolidNodesTakeTheSolidFieldNotTheFluidExtension) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  auto ball_at = [&](const Vec2& shift) { return body_moved_by(s, mesh, shift); };
  // The body moves down by 0.6 of a patch height between the two meshes.
  const double patch_h = std::abs(mesh.nodes[mesh.patches[0].node[6]].y() - mesh.nodes[mesh.patches[0].node[0]].y());
  const fsi::fe::CutMesh current = ball_at({0.0, 0.0}), next = ball_at({0.0, -0.6 * patch_h});
  // A rigid rotation of 0.8 rad plus a translation in the solid (linear in x), and in the
  // fluid a field no solid could have (u = 5 x: det(I - grad u) = 16), standing for an
  // extension that does not continue the solid's field.
  const double c = std::cos(0.8), sn = std::sin(0.8);
  Eigen::Matrix2d grad_u;
  grad_u << 1.0 - c, -sn, sn, 1.0 - c;
  const Vec2 u0(0.3, -0.2);
  auto solid_u = [&](const Vec2& x) { return Vec2(grad_u * x + u0); };
  auto solid_v = [&](const Vec2& x) { return Vec2(0.5 - 2.0 * x.y(), -0.4 + 2.0 * x.x()); };
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2 u = current.touches_solid[n] ? solid_u(current.x[n]) : Vec2(5.0 * current.x[n]);
    const Vec2 v = current.touches_solid[n] ? solid_v(current.x[n]) : Vec2::Zero();
    solution.segment(fsi::kFieldsPerNode * n, 4) << v.x(), v.y(), u.x(), u.y();
  }
  fsi::core::InitialGuessStats stats;
  const Eigen::VectorXd x = fsi::core::initial_guess(mesh, buckets, current, next, solution, &stats);
  // Nodes in the body on the new mesh whose place lies inside a fluid sub-element of the
  // current one: interpolation there would give the fluid's values (u = 5 x here).
  int newly_solid = 0, exact = 0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (!next.touches_solid[n] || mesh.on_wall[n]) continue;
    const fsi::fe::Location loc = fsi::fe::locate(current, buckets, next.x[n], 1e-6);
    if (loc.element < 0 || current.elements[loc.element].phase != fsi::Phase::fluid) continue;
    ++newly_solid;
    const Vec2 u = solid_u(next.x[n]), v = solid_v(next.x[n]);
    const Eigen::Vector4d want(v.x(), v.y(), u.x(), u.y());
    if ((x.segment(fsi::kFieldsPerNode * n, 4) - want).norm() < 1e-9) ++exact;
  }
  ASSERT_GT(newly_solid, 5) << "the move must cover nodes that were in the fluid";
  EXPECT_GT(stats.extrapolated_nodes, 5);
  // Nodes in patches without any solid sub-element yet keep the interpolated value.
  EXPECT_GE(exact, 0.8 * newly_solid) << exact << " of " << newly_solid;
  // Nodes of the body on both meshes that moved: interpolated in the solid, exact too.
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (next.x[n] == current.x[n] || !current.touches_solid[n] || !next.touches_solid[n] || mesh.on_wall[n]) continue;
    const fsi::fe::Location loc = fsi::fe::locate(current, buckets, next.x[n], 1e-6);
    if (loc.element < 0 || current.elements[loc.element].phase != fsi::Phase::solid) continue;
    EXPECT_NEAR(x[fsi::kFieldsPerNode * n + fsi::kUx], solid_u(next.x[n]).x(), 1e-9);
  }
}

TEST(InitialGuess, NodesInPatchesTheBodyHadNotReachedContinueTheNeighbouringSolidField) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  auto ball_at = [&](const Vec2& shift) { return body_moved_by(s, mesh, shift); };
  // A move of 0.7 patch heights (a step moves the interface by less than a patch): the
  // body covers nodes of patches in which it had no solid sub-element at all, so their
  // own patch has no solid field to continue (30 nodes here; all 30 kept the fluid's
  // extension before the neighbouring patches were asked).
  // The height of the patch row below the body (the mesh is graded towards the ground).
  const double bottom = s.body.center_m.y - s.body.radius_m;
  double patch_h = 0.0;
  for (const auto& patch : mesh.patches) {
    const double y0 = mesh.nodes[patch.node[0]].y(), y1 = mesh.nodes[patch.node[6]].y();
    if (std::min(y0, y1) <= bottom && bottom < std::max(y0, y1)) patch_h = std::abs(y1 - y0);
  }
  ASSERT_GT(patch_h, 0.0);
  const fsi::fe::CutMesh current = ball_at({0.0, 0.0}), next = ball_at({0.0, -0.7 * patch_h});
  std::vector<char> patch_has_solid(mesh.patches.size(), 0);
  for (const fsi::fe::SubElement& e : current.elements)
    if (e.phase == fsi::Phase::solid) patch_has_solid[e.patch] = 1;
  // The solid field is a translation (linear, so any solid sub-element continues it
  // exactly); the fluid's extension u = 5 x has det(I - grad u) = 16.
  const Vec2 u0(0.01, -0.02), v0(0.1, -0.3);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vec2 u = current.touches_solid[n] ? u0 : Vec2(5.0 * current.x[n]);
    const Vec2 v = current.touches_solid[n] ? v0 : Vec2::Zero();
    solution.segment(fsi::kFieldsPerNode * n, 4) << v.x(), v.y(), u.x(), u.y();
  }
  const Eigen::VectorXd x = fsi::core::initial_guess(mesh, buckets, current, next, solution);
  int without_solid = 0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (!next.touches_solid[n] || mesh.on_wall[n]) continue;
    const fsi::fe::Location loc = fsi::fe::locate(current, buckets, next.x[n], 1e-6);
    if (loc.element < 0 || patch_has_solid[current.elements[loc.element].patch]) continue;
    ++without_solid;
    const Eigen::Vector4d want(v0.x(), v0.y(), u0.x(), u0.y());
    EXPECT_LT((x.segment(fsi::kFieldsPerNode * n, 4) - want).norm(), 1e-9)
        << "node " << n << " at (" << next.x[n].x() << ", " << next.x[n].y() << ")";
  }
  ASSERT_GT(without_solid, 0) << "the move must cover nodes of patches without a solid sub-element";
}

TEST(InitialGuess, UnchangedMeshGivesTheSolutionBackWithWallVelocitiesZero) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) { return fsi::interface::initial_distance(s.body, x); });
  Eigen::VectorXd solution = Eigen::VectorXd::LinSpaced(fsi::kFieldsPerNode * mesh.num_nodes(), -1.0, 1.0);
  fsi::core::InitialGuessStats stats;
  const Eigen::VectorXd x = fsi::core::initial_guess(mesh, buckets, cut, cut, solution, &stats);
  EXPECT_EQ(stats.moved_nodes, 0);
  EXPECT_EQ(stats.extrapolated_nodes, 0);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int f = 0; f < fsi::kFieldsPerNode; ++f) {
      const double want = mesh.on_wall[n] && f < 2 ? 0.0 : solution[fsi::kFieldsPerNode * n + f];
      ASSERT_EQ(x[fsi::kFieldsPerNode * n + f], want) << "node " << n << " field " << f;
    }
}

}  // namespace
