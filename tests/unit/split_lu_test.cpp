// The two-block LU (solve/split_lu.hpp) against the LU of the whole matrix: the same
// solution on a block lower triangular matrix, and the whole matrix factorized (still
// the right solution) as soon as a coupled row depends on an extension unknown.
#include "solve/split_lu.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace {

using Matrix = fsi::solve::SparseLU::Matrix;

/// A diagonally dominant n x n matrix with random off-diagonal entries, none in the rows
/// of coupled unknowns and columns of extension unknowns (extension: every third).
Matrix block_lower_triangular(int n, const std::vector<char>& extension, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 8.0 + d(rng));
    for (int m = 0; m < 4; ++m) {
      const int j = pick(rng);
      if (j == i || (!extension[i] && extension[j])) continue;
      t.emplace_back(i, j, d(rng));
    }
  }
  Matrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

std::vector<char> every_third(int n) {
  std::vector<char> e(n);
  for (int i = 0; i < n; ++i) e[i] = i % 3 == 2;
  return e;
}

TEST(SplitLU, SolvesABlockLowerTriangularMatrixInTwoBlocks) {
  const int n = 300;
  const std::vector<char> extension = every_third(n);
  const Matrix a = block_lower_triangular(n, extension, 1);
  fsi::solve::SplitLU split;
  ASSERT_TRUE(split.factorize(a, extension));
  EXPECT_TRUE(split.split());
  EXPECT_EQ(split.coupled_size(), 200);
  fsi::solve::SparseLU whole;
  ASSERT_TRUE(whole.factorize(a));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = d(rng);
  const Eigen::VectorXd x = split.solve(b), y = whole.solve(b);
  EXPECT_LT((a * x - b).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((x - y).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SplitLU, FactorizesTheWholeMatrixWhenACoupledRowSeesAnExtensionUnknown) {
  const int n = 120;
  const std::vector<char> extension = every_third(n);
  Matrix a = block_lower_triangular(n, extension, 3);
  fsi::solve::SplitLU split;
  ASSERT_TRUE(split.factorize(a, extension));
  EXPECT_TRUE(split.split());
  // Row 0 (coupled) now depends on unknown 2 (extension).
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (Matrix::InnerIterator it(a, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  t.emplace_back(0, 2, 0.5);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  ASSERT_TRUE(split.factorize(a, extension));
  EXPECT_FALSE(split.split());
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  EXPECT_LT((a * split.solve(b) - b).cwiseAbs().maxCoeff(), 1e-12);
  // The same pattern with that entry exactly zero: split again.
  for (Matrix::InnerIterator it(a, 2); it; ++it)
    if (it.row() == 0) it.valueRef() = 0.0;
  ASSERT_TRUE(split.factorize(a, extension));
  EXPECT_TRUE(split.split());
  EXPECT_LT((a * split.solve(b) - b).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SplitLU, TwoThreadsGiveTheSameBitsAsOne) {
  const int n = 3000;
  const std::vector<char> extension = every_third(n);
  const Matrix a = block_lower_triangular(n, extension, 5);
  fsi::solve::SplitLU one, two;
  ASSERT_TRUE(one.factorize(a, extension, 1));
  ASSERT_TRUE(two.factorize(a, extension, 2));
  ASSERT_TRUE(two.split());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd x1 = one.solve(b), x2 = two.solve(b);
  EXPECT_EQ(0, std::memcmp(x1.data(), x2.data(), sizeof(double) * n));
  EXPECT_LT((a * x2 - b).cwiseAbs().maxCoeff(), 1e-12);
  // A singular extension block is reported from its thread as from the caller's.
  Matrix singular = a;
  for (int j = 0; j < n; ++j)
    for (Matrix::InnerIterator it(singular, j); it; ++it)
      if (extension[it.row()]) it.valueRef() = 0.0;
  EXPECT_FALSE(two.factorize(singular, extension, 2));
  EXPECT_FALSE(one.factorize(singular, extension, 1));
}

TEST(SplitLU, WithoutExtensionUnknownsItIsThePlainLU) {
  const int n = 60;
  const std::vector<char> none(n, 0);
  const Matrix a = block_lower_triangular(n, none, 4);
  fsi::solve::SplitLU split;
  ASSERT_TRUE(split.factorize(a, none));
  EXPECT_FALSE(split.split());
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  EXPECT_LT((a * split.solve(b) - b).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
