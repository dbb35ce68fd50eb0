#include "solve/gmres.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using Matrix = fsi::solve::SparseLU::Matrix;

// 1D Laplacian plus a nonsymmetric convection part, rows scaled by `row_scale` (as the FSI
// system's momentum, displacement and pressure rows differ by orders of magnitude).
Matrix convection_diffusion(int n, double convection, double row_scale_ratio) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    const double s = (i % 2 == 0) ? 1.0 : row_scale_ratio;
    t.emplace_back(i, i, 2.0 * s);
    if (i > 0) t.emplace_back(i, i - 1, (-1.0 - convection) * s);
    if (i + 1 < n) t.emplace_back(i, i + 1, (-1.0 + convection) * s);
  }
  Matrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

Eigen::VectorXd inverse_row_max(const Matrix& a) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(a.rows());
  for (int c = 0; c < a.outerSize(); ++c)
    for (Matrix::InnerIterator it(a, c); it; ++it) w[it.row()] = std::max(w[it.row()], std::abs(it.value()));
  return w.cwiseInverse();
}

TEST(Gmres, AnOlderFactorizationAsPreconditionerGivesTheNewSystemsSolution) {
  const int n = 300;
  const Matrix old_matrix = convection_diffusion(n, 0.3, 1e6);
  Matrix a = convection_diffusion(n, 0.35, 1e6);  // the "next iterate's" Jacobian
  for (int k = a.outerIndexPtr()[150]; k < a.outerIndexPtr()[151]; ++k) a.valuePtr()[k] *= 1.5;  // a local change
  fsi::solve::SparseLU lu;
  ASSERT_TRUE(lu.factorize(old_matrix));
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd b = a * x_exact;
  Eigen::VectorXd x;
  const fsi::solve::GmresResult r = fsi::solve::gmres(
      a, b, [&](const Eigen::VectorXd& v) { return lu.solve(v); }, inverse_row_max(a), 1e-10, 60, x);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.relative_residual, 1e-10);
  EXPECT_LT(r.iterations, 40);  // far fewer than n: the old factorization is a good preconditioner
  EXPECT_LT((x - x_exact).norm(), 1e-6 * x_exact.norm());
  // The true residual, not only GMRES's recurrence, meets the tolerance.
  const Eigen::VectorXd w = inverse_row_max(a);
  EXPECT_LE((w.cwiseProduct(b - a * x)).norm(), 1.01e-10 * (w.cwiseProduct(b)).norm());
}

TEST(Gmres, ReportsNoConvergenceWithinTooFewIterations) {
  const int n = 200;
  const Matrix a = convection_diffusion(n, 0.2, 1.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x;
  // Identity "preconditioner": the Laplacian needs about n iterations, not 5.
  const fsi::solve::GmresResult r = fsi::solve::gmres(
      a, b, [](const Eigen::VectorXd& v) { return v; }, Eigen::VectorXd::Ones(n), 1e-8, 5, x);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_GT(r.relative_residual, 1e-8);
  EXPECT_LT(r.relative_residual, 1.0);  // but it made progress, and x reflects it
  EXPECT_LT((b - a * x).norm(), b.norm());
}

TEST(Gmres, GivesUpEarlyWhenItsRatePredictsNoConvergenceWithinTheBudget) {
  const int n = 400;
  const Matrix a = convection_diffusion(n, 0.2, 1.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x;
  // Unpreconditioned, the 400-point Laplacian gains far less than the 1e-8 that 40
  // iterations would need at its rate: the caller is better off refactorizing now.
  const fsi::solve::GmresResult r = fsi::solve::gmres(
      a, b, [](const Eigen::VectorXd& v) { return v; }, Eigen::VectorXd::Ones(n), 1e-8, 40, x);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.given_up);
  EXPECT_GE(r.iterations, 10);
  EXPECT_LT(r.iterations, 20);
  // With a budget the rate can meet (a good preconditioner), it does not give up.
  fsi::solve::SparseLU lu;
  ASSERT_TRUE(lu.factorize(convection_diffusion(n, 0.25, 1.0)));
  const fsi::solve::GmresResult good = fsi::solve::gmres(
      a, b, [&](const Eigen::VectorXd& v) { return lu.solve(v); }, Eigen::VectorXd::Ones(n), 1e-8, 40, x);
  EXPECT_TRUE(good.converged);
  EXPECT_FALSE(good.given_up);
}

TEST(Gmres, AZeroRightHandSideIsSolvedByZero) {
  const Matrix a = convection_diffusion(20, 0.0, 1.0);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(20);
  const fsi::solve::GmresResult r = fsi::solve::gmres(
      a, Eigen::VectorXd::Zero(20), [](const Eigen::VectorXd& v) { return v; }, Eigen::VectorXd::Ones(20), 1e-8, 5, x);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(x.norm(), 0.0);
}

}  // namespace
