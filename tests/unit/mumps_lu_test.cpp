// The MUMPS LU of the coupled block (solve/mumps_lu.hpp): the solution of A x = b to
// round-off, the analysis reused while the pattern stays and rerun when it changes,
// singular matrices reported, zero diagonals pivoted round, and the same bits from every
// instance whatever was factorized before.
#include "solve/mumps_lu.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <thread>
#include <vector>

namespace {

using Matrix = fsi::solve::MumpsLU::Matrix;

Matrix from_triplets(int n, const std::vector<Eigen::Triplet<double>>& t) {
  Matrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

// A 2D convection-diffusion stencil on an m x m grid (5-point, nonsymmetric).
Matrix grid_operator(int m, double convection) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int r = i * m + j;
      t.emplace_back(r, r, 4.0);
      if (i > 0) t.emplace_back(r, r - m, -1.0 - convection);
      if (i + 1 < m) t.emplace_back(r, r + m, -1.0 + convection);
      if (j > 0) t.emplace_back(r, r - 1, -1.0 - 0.5 * convection);
      if (j + 1 < m) t.emplace_back(r, r + 1, -1.0 + 0.5 * convection);
    }
  return from_triplets(m * m, t);
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& x_exact) {
  return (x - x_exact).cwiseAbs().maxCoeff() / x_exact.cwiseAbs().maxCoeff();
}

TEST(MumpsLU, SolvesAndReusesTheAnalysisWhileThePatternStays) {
  fsi::solve::MumpsLU lu;
  const int m = 40, n = m * m;
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (double c : {0.0, 0.3, 0.7}) {
    const Matrix a = grid_operator(m, c);
    ASSERT_TRUE(lu.factorize(a));
    EXPECT_LT(relative_error(lu.solve(a * x_exact), x_exact), 1e-12);
  }
  EXPECT_EQ(lu.symbolic_analyses(), 1);
  // Another pattern (one more entry) is analysed again and solved right.
  std::vector<Eigen::Triplet<double>> t;
  const Matrix a = grid_operator(m, 0.2);
  for (int c = 0; c < n; ++c)
    for (Matrix::InnerIterator it(a, c); it; ++it) t.emplace_back(it.row(), c, it.value());
  t.emplace_back(0, n - 1, 0.5);
  const Matrix b = from_triplets(n, t);
  ASSERT_TRUE(lu.factorize(b));
  EXPECT_EQ(lu.symbolic_analyses(), 2);
  EXPECT_LT(relative_error(lu.solve(b * x_exact), x_exact), 1e-12);
}

TEST(MumpsLU, ReportsASingularMatrix) {
  const int m = 10, n = m * m;
  Matrix a = grid_operator(m, 0.1);
  for (int c = 0; c < n; ++c)  // row 37 all zero
    for (Matrix::InnerIterator it(a, c); it; ++it)
      if (it.row() == 37) it.valueRef() = 0.0;
  fsi::solve::MumpsLU lu;
  EXPECT_FALSE(lu.factorize(a));
  EXPECT_FALSE(lu.factorized());
  // ... and factorizes the next regular one with the same pattern.
  EXPECT_TRUE(lu.factorize(grid_operator(m, 0.1)));
}

// A saddle point [A B^T; B 0] whose constraint rows have a zero (or 1e-13) diagonal, as
// the FSI Jacobian's pressure rows can: those diagonal entries must not be pivots.
TEST(MumpsLU, PivotsRoundAZeroDiagonal) {
  const int n = 60, m = n - 1;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.4);
    if (i + 1 < n) t.emplace_back(i, i + 1, -0.6);
  }
  for (int i = 0; i < m; ++i) {
    t.emplace_back(n + i, i, -1.0);
    t.emplace_back(n + i, i + 1, 1.0);
    t.emplace_back(i, n + i, -1.0);
    t.emplace_back(i + 1, n + i, 1.0);
    t.emplace_back(n + i, n + i, i % 2 ? 0.0 : 1e-13);
  }
  const Matrix s = from_triplets(n + m, t);
  fsi::solve::MumpsLU lu;
  ASSERT_TRUE(lu.factorize(s));
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(n + m, -1.0, 2.0);
  EXPECT_LT(relative_error(lu.solve(s * x_exact), x_exact), 1e-9);
}

// Determinism: a factorization depends on the matrix alone, not on what the instance
// factorized before (a checkpoint rebuilds its factorization in a fresh one), and two
// instances on two threads give the bits one gives alone (without MumpsLU's lock the two
// crashed inside MUMPS).
TEST(MumpsLU, TheSameBitsFromEveryInstanceAndThread) {
  const int m = 60, n = m * m;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  Matrix a = grid_operator(m, 0.4);
  for (int c = 0; c < n; ++c)
    for (Matrix::InnerIterator it(a, c); it; ++it) it.valueRef() *= 1.0 + d(rng);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);

  fsi::solve::MumpsLU fresh, used;
  ASSERT_TRUE(used.factorize(grid_operator(m, 0.9)));
  ASSERT_TRUE(used.factorize(a));
  ASSERT_TRUE(fresh.factorize(a));
  const Eigen::VectorXd x_fresh = fresh.solve(b), x_used = used.solve(b);
  EXPECT_EQ(0, std::memcmp(x_fresh.data(), x_used.data(), sizeof(double) * n));

  const Matrix other = grid_operator(m, 0.6);
  fsi::solve::MumpsLU one, two;
  Eigen::VectorXd x_one, x_two;
  std::thread worker([&] {
    if (two.factorize(other)) x_two = two.solve(b);
  });
  if (one.factorize(a)) x_one = one.solve(b);
  worker.join();
  ASSERT_EQ(x_one.size(), n);
  ASSERT_EQ(x_two.size(), n);
  EXPECT_EQ(0, std::memcmp(x_one.data(), x_fresh.data(), sizeof(double) * n));
  fsi::solve::MumpsLU alone;
  ASSERT_TRUE(alone.factorize(other));
  const Eigen::VectorXd x_alone = alone.solve(b);
  EXPECT_EQ(0, std::memcmp(x_two.data(), x_alone.data(), sizeof(double) * n));
}

}  // namespace
