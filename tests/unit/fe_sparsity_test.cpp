// The fixed sparsity pattern of the 5-field FSI system (vx, vy, ux, uy, p) holds every
// coupling an element or a CIP edge produces, for any interface position, and nothing
// the coupling tables exclude.
#include "solve/sparsity.hpp"

#include <gtest/gtest.h>

#include "fe/stabilization_edges.hpp"
#include "solve/sparse_lu.hpp"
#include "fe_test_meshes.hpp"

namespace {

using fsi::test::Vec2;

TEST(FeSparsity, PatternCoversElementAndStabilizationCouplings) {
  const auto mesh = fsi::test::graded_square(6);
  // Rows: v -> {v, u, p}; u -> {v, u}; p -> {v, p}. Neighbouring patches: p-p only.
  const fsi::solve::FieldCoupling coupling{{1, 1, 1, 1, 1}, {1, 1, 1, 1, 1}, {1, 1, 1, 1, 0},
                                           {1, 1, 1, 1, 0}, {1, 1, 0, 0, 1}};
  fsi::solve::FieldCoupling neighbor(5, std::vector<char>(5, 0));
  neighbor[4][4] = 1;
  const auto a = fsi::solve::build_pattern(mesh, 5, coupling, neighbor);
  for (double shift : {0.0, 0.013, 0.031}) {
    const Vec2 c(shift, -shift);
    const auto cut = fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return (x - c).norm() - 0.5; });
    for (const auto& e : cut.elements)
      for (int i = 0; i < e.vertices; ++i)
        for (int j = 0; j < e.vertices; ++j)
          for (int fr = 0; fr < 5; ++fr)
            for (int fc = 0; fc < 5; ++fc)
              ASSERT_EQ(fsi::solve::value_index(a, 5 * e.node[i] + fr, 5 * e.node[j] + fc) >= 0,
                        coupling[fr][fc] == 1);
    for (const auto& se : fsi::fe::build_stabilization_edges(cut)) {
      const auto& e1 = cut.elements[se.element1];
      const auto& e2 = cut.elements[se.element2];
      for (int i = 0; i < e1.vertices; ++i)
        for (int j = 0; j < e2.vertices; ++j) {
          EXPECT_GE(fsi::solve::value_index(a, 5 * e1.node[i] + 4, 5 * e2.node[j] + 4), 0);
          EXPECT_GE(fsi::solve::value_index(a, 5 * e2.node[j] + 4, 5 * e1.node[i] + 4), 0);
        }
    }
  }
  // u never couples to p through a neighbour patch.
  EXPECT_LT(fsi::solve::value_index(a, 5 * 0 + 2, 5 * (mesh.num_nodes() - 1) + 4), 0);
}

TEST(FeSparsity, SymbolicAnalysisIsRedoneWhenOnlyTheRowIndicesDiffer) {
  // Two 3x3 patterns with the same column counts but different rows.
  auto matrix = [](int off_row) {
    std::vector<Eigen::Triplet<double>> t{{0, 0, 4.0}, {1, 1, 4.0}, {2, 2, 4.0}, {off_row, 2, 1.0}};
    fsi::solve::SparseMatrix m(3, 3);
    m.setFromTriplets(t.begin(), t.end());
    m.makeCompressed();
    return m;
  };
  fsi::solve::SparseLU lu;
  const Eigen::Vector3d x(1.0, -2.0, 3.0);
  for (int row : {0, 1}) {
    const auto m = matrix(row);
    ASSERT_TRUE(lu.factorize(m));
    EXPECT_LT((lu.solve(m * x) - x).norm(), 1e-14);
  }
  EXPECT_EQ(lu.symbolic_analyses(), 2);
}

}  // namespace
