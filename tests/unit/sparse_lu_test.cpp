#include "solve/sparse_lu.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using Matrix = fsi::solve::SparseLU::Matrix;

// 1D Laplacian plus a nonsymmetric convection part: a small but real LU problem.
Matrix convection_diffusion(int n, double convection) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0 - convection);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0 + convection);
  }
  Matrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

TEST(SparseLU, SolvesAndReusesTheSymbolicAnalysis) {
  fsi::solve::SparseLU lu;
  for (double c : {0.0, 0.3, 0.7}) {
    const Matrix a = convection_diffusion(200, c);
    ASSERT_TRUE(lu.factorize(a));
    const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(200, -1.0, 2.0);
    const Eigen::VectorXd x = lu.solve(a * x_exact);
    EXPECT_LT((x - x_exact).norm(), 1e-10 * x_exact.norm());
  }
  EXPECT_EQ(lu.symbolic_analyses(), 1);  // same pattern: analysed once
  EXPECT_GT(lu.rcond(), 0.0);
}

// A saddle point [A B^T; B D] whose constraint block D is stored but zero or tiny on its
// diagonal, as the pressure rows of the FSI Jacobian can be: such diagonal entries must not
// be taken as pivots (SparseLU takes a diagonal pivot down to 1e-8 of its column).
TEST(SparseLU, PivotsOffTheDiagonalWhereTheDiagonalIsZeroOrTiny) {
  const int n = 60, m = n - 1;
  std::vector<Eigen::Triplet<double>> t;
  const Matrix a = convection_diffusion(n, 0.4);
  for (int c = 0; c < n; ++c)
    for (Matrix::InnerIterator it(a, c); it; ++it) t.emplace_back(it.row(), c, it.value());
  for (int i = 0; i < m; ++i) {  // B: differences of neighbouring unknowns
    t.emplace_back(n + i, i, -1.0);
    t.emplace_back(n + i, i + 1, 1.0);
    t.emplace_back(i, n + i, -1.0);
    t.emplace_back(i + 1, n + i, 1.0);
    t.emplace_back(n + i, n + i, i % 2 ? 0.0 : 1e-13);
  }
  Matrix s(n + m, n + m);
  s.setFromTriplets(t.begin(), t.end());
  s.makeCompressed();
  fsi::solve::SparseLU lu;
  ASSERT_TRUE(lu.factorize(s));
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(n + m, -1.0, 2.0);
  const Eigen::VectorXd x = lu.solve(s * x_exact);
  EXPECT_LT((x - x_exact).norm(), 1e-8 * x_exact.norm());
}

TEST(SparseLU, ReportsASingularMatrix) {
  Matrix a = convection_diffusion(10, 0.0);
  for (int k = a.outerIndexPtr()[3]; k < a.outerIndexPtr()[4]; ++k) a.valuePtr()[k] = 0.0;
  fsi::solve::SparseLU lu;
  EXPECT_FALSE(lu.factorize(a));
  EXPECT_FALSE(lu.factorized());
}

}  // namespace
