// Edges of the anisotropic CIP stabilization and the stabilization form itself:
// normal cell sizes h_n (|K|/|e| for sub-quads, 2|K|/|e| for triangles), E_h^i vs E_h^0
// classification, both sides' quadrature points coincide; S_aniso is symmetric,
// positive semi-definite, vanishes for linear pressures away from cut patches and
// ignores solid cells; the wall-film factor scales only thin fluid cells at a wall.
#include "fe/stabilization_edges.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "fe_test_meshes.hpp"
#include "forms/pressure_stabilization.hpp"

namespace {

using fsi::test::Vec2;

Vec2 point_of(const fsi::fe::CutMesh& cut, const fsi::fe::SubElement& e, const fsi::fe::ShapeValues& s) {
  Vec2 x = Vec2::Zero();
  for (int i = 0; i < e.vertices; ++i) x += s.value[i] * cut.x[e.node[i]];
  return x;
}

TEST(FeStabilizationEdges, NormalSizesAndClassificationOnAnAnisotropicMesh) {
  // Patches 0.4 x 0.05: sub-quads 0.2 x 0.025.
  const auto mesh = fsi::test::block_mesh(5, 8, 2.0, 0.4);
  const Vec2 c(1.03, 0.21);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return x.x() - c.x() + 0.3 * (x.y() - c.y()); });
  const auto edges = fsi::fe::build_stabilization_edges(cut);
  // Interior sub-element edges: (2 * 5 - 1) * 16 vertical + (2 * 8 - 1) * 10 horizontal
  // for the quads, plus 2 diagonals... count: every element edge used twice, boundary once.
  int used = 0;
  for (const auto& e : cut.elements) used += e.vertices;
  const int boundary = 2 * (2 * 5 + 2 * 8);
  EXPECT_EQ(static_cast<int>(edges.size()), (used - boundary) / 2);
  int quad_quad = 0;
  for (const auto& se : edges) {
    const auto& e1 = cut.elements[se.element1];
    const auto& e2 = cut.elements[se.element2];
    EXPECT_EQ(se.in_cut_patch, e1.vertices == 3 || e2.vertices == 3);
    for (int s = 0; s < 2; ++s) {
      const auto& e = s == 0 ? e1 : e2;
      const double hn = s == 0 ? se.hn1_m : se.hn2_m;
      const double area = fsi::fe::element_area(cut, e);
      EXPECT_NEAR(hn, (e.vertices == 3 ? 2.0 : 1.0) * area / se.length_m, 1e-14);
    }
    if (!se.in_cut_patch) {
      ++quad_quad;
      // Axis-aligned sub-quads: h_n is the other side length.
      const bool vertical = se.length_m < 0.1 && std::abs(se.length_m - 0.025) < 1e-12;
      EXPECT_NEAR(se.hn1_m, vertical ? 0.2 : 0.025, 1e-12);
      EXPECT_NEAR(se.hn2_m, vertical ? 0.2 : 0.025, 1e-12);
    }
    EXPECT_NEAR(se.weight[0] + se.weight[1], se.length_m, 1e-15);
    for (int q = 0; q < 2; ++q)
      EXPECT_NEAR((point_of(cut, e1, se.side1[q]) - point_of(cut, e2, se.side2[q])).norm(), 0.0, 1e-14);
  }
  EXPECT_GT(quad_quad, 100);
}

/// Dense copy of the p-p block of S_aniso on a scalar (stride 1) system.
Eigen::MatrixXd stabilization_matrix(const fsi::mesh::PatchMesh& mesh, const fsi::fe::CutMesh& cut,
                                     double wall_film_factor = 0.0) {
  auto a = fsi::solve::build_pattern(mesh, 1, {{1}}, {{1}});
  const auto edges = fsi::fe::build_stabilization_edges(cut);
  fsi::forms::add_pressure_stabilization(mesh, cut, edges, 0.1, 1, 0, a, 0.0, wall_film_factor);
  return Eigen::MatrixXd(a);
}

TEST(FePressureStabilization, WallFilmFactorScalesOnlyThinFluidCellsAtAWall) {
  // Patches 0.25 x 0.1 on (0,1) x (0,0.4); the body fills everything above y = 0.005, so
  // the fluid is a film of 5 mm in the bottom patch row (the ground, when it is a wall).
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{0.0, 1.0, 4, 0.0, 0.0}};
  b.y = {fsi::AxisPiece{0.0, 0.4, 4, 0.0, 0.0}};
  fsi::MeshSpec spec;
  spec.blocks = {b};
  const double film_m = 0.005;
  auto phi = [film_m](const Vec2& x) { return film_m - x.y(); };
  const auto ground = fsi::mesh::build_patch_mesh(spec, {fsi::Segment2{{0.0, 0.0}, {1.0, 0.0}}});
  const auto cut = fsi::fe::build_cut_mesh(ground, phi);
  const Eigen::MatrixXd s0 = stabilization_matrix(ground, cut);
  const Eigen::MatrixXd s1 = stabilization_matrix(ground, cut, 1.0);
  ASSERT_GT(s0.norm(), 0.0);
  // h = h_K (about the film height) instead of h_P = 0.25: (0.005 / 0.25)^2 = 4e-4.
  EXPECT_GT(s1.norm(), 1e-4 * s0.norm());
  EXPECT_LT(s1.norm(), 1e-3 * s0.norm());
  EXPECT_LT((s1 - s1.transpose()).norm(), 1e-14 * s1.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s1).eigenvalues().minCoeff(), -1e-12 * s1.norm());
  // kappa h_K above h_P: h_P as without the factor.
  EXPECT_LT((stabilization_matrix(ground, cut, 1e3) - s0).norm(), 1e-14 * s0.norm());
  // The same film without a wall under it (an open boundary) is left alone.
  const auto open = fsi::mesh::build_patch_mesh(spec, {});
  const auto open_cut = fsi::fe::build_cut_mesh(open, phi);
  EXPECT_LT((stabilization_matrix(open, open_cut, 1.0) - stabilization_matrix(open, open_cut)).norm(),
            1e-14 * s0.norm());
}

TEST(FePressureStabilization, SymmetricSemiDefiniteAndZeroForLinearsOnUncutMeshes) {
  const auto mesh = fsi::test::graded_square(5);
  auto linear = [&](const fsi::fe::CutMesh& cut) {
    Eigen::VectorXd p(mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) p[i] = 2.0 + cut.x[i].x() - 4.0 * cut.x[i].y();
    return p;
  };
  {  // No interface in the domain: pure jump form, consistent for linear p.
    const auto cut = fsi::fe::build_cut_mesh(mesh, [](const Vec2&) { return 1.0; });
    const Eigen::MatrixXd s = stabilization_matrix(mesh, cut);
    EXPECT_GT(s.norm(), 0.0);
    EXPECT_LT((s * linear(cut)).norm(), 1e-12 * s.norm());
  }
  const Vec2 c(0.1, 0.05);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return (x - c).norm() - 0.45; });
  const Eigen::MatrixXd s = stabilization_matrix(mesh, cut);
  EXPECT_LT((s - s.transpose()).norm(), 1e-14 * s.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s).eigenvalues().minCoeff(), -1e-12 * s.norm());
  // Rows of nodes without a fluid sub-element stay empty (solid cells dropped).
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if (!cut.touches_fluid[i]) {
      EXPECT_EQ(s.row(i).norm(), 0.0) << "node " << i;
    }
  // The averaged form on E_h^i is not consistent: linear p see it, but only near the
  // interface (rows of nodes far from cut patches vanish).
  const Eigen::VectorXd r = s * linear(cut);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if ((cut.x[i] - c).norm() > 0.45 + 2 * 0.4) {
      EXPECT_NEAR(r[i], 0.0, 1e-12 * s.norm());
    }
}

}  // namespace
