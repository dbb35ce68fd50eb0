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

TEST(SparseLU, ReportsASingularMatrix) {
  Matrix a = convection_diffusion(10, 0.0);
  for (int k = a.outerIndexPtr()[3]; k < a.outerIndexPtr()[4]; ++k) a.valuePtr()[k] = 0.0;
  fsi::solve::SparseLU lu;
  EXPECT_FALSE(lu.factorize(a));
  EXPECT_FALSE(lu.factorized());
}

}  // namespace
