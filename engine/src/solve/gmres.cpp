#include "solve/gmres.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace fsi::solve {

namespace {

/// One Arnoldi cycle of at most m iterations on W A M^-1 y = W b (b the current residual);
/// returns the correction M^-1 W^-1 V y and adds its iterations to `result`.
Eigen::VectorXd gmres_cycle(const SparseLU::Matrix& a, const Eigen::VectorXd& wb,
                            const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                            const Eigen::VectorXd& row_weight, const Eigen::VectorXd& inv_weight,
                            double tol_abs, int m, GmresResult& result) {
  const double beta = wb.norm();
  std::vector<Eigen::VectorXd> basis;
  basis.reserve(m + 1);
  basis.push_back(wb / beta);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);  // Hessenberg, rotated in place
  Eigen::VectorXd cs = Eigen::VectorXd::Zero(m), sn = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1);  // rotated right-hand side
  g[0] = beta;
  int k = 0;  // columns built
  for (; k < m; ++k) {
    Eigen::VectorXd w = row_weight.cwiseProduct(a * precondition(inv_weight.cwiseProduct(basis[k])));
    if (!w.allFinite()) break;
    ++result.iterations;
    // Modified Gram-Schmidt, twice: the basis must stay orthogonal to the last bit when
    // the tolerance is tight and the preconditioned operator is nearly the identity.
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i <= k; ++i) {
        const double hik = basis[i].dot(w);
        h(i, k) += hik;
        w -= hik * basis[i];
      }
    h(k + 1, k) = w.norm();
    for (int i = 0; i < k; ++i) {  // earlier rotations on the new column
      const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
      h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
      h(i, k) = t;
    }
    const double r = std::hypot(h(k, k), h(k + 1, k));
    cs[k] = r > 0.0 ? h(k, k) / r : 1.0;
    sn[k] = r > 0.0 ? h(k + 1, k) / r : 0.0;
    h(k, k) = r;
    h(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] = cs[k] * g[k];
    const double next_norm = w.norm();
    if (std::abs(g[k + 1]) <= tol_abs || !(next_norm > 0.0)) {
      ++k;
      break;
    }
    basis.push_back(w / next_norm);
  }
  if (k == 0) return Eigen::VectorXd::Zero(wb.size());
  // y from the triangular system, then M^-1 W^-1 (V y): one more preconditioner solve
  // instead of keeping every M^-1 v.
  const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  Eigen::VectorXd combination = Eigen::VectorXd::Zero(wb.size());
  for (int i = 0; i < k; ++i) combination += y[i] * basis[i];
  return precondition(inv_weight.cwiseProduct(combination));
}

}  // namespace

GmresResult gmres(const SparseLU::Matrix& a, const Eigen::VectorXd& b,
                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                  const Eigen::VectorXd& row_weight, double rel_tol, int max_iterations,
                  Eigen::VectorXd& x) {
  GmresResult result;
  x.setZero(b.size());
  // The weighted system W A M^-1 y = W b; M^-1 of a weighted vector undoes the weight
  // first, so that W A M^-1 is close to the identity when M is close to A.
  const Eigen::VectorXd inv_weight = row_weight.cwiseInverse();
  Eigen::VectorXd wr = row_weight.cwiseProduct(b);
  const double beta = wr.norm();
  if (!(beta > 0.0) || !std::isfinite(beta)) {
    result.converged = beta == 0.0;
    result.relative_residual = beta == 0.0 ? 0.0 : 1.0;
    return result;
  }
  // Restarted from the true residual: with an ill-conditioned preconditioner (a stale
  // factorization next to a sliver sub-element) the Arnoldi recurrence's residual drifts
  // from the true one (claimed 1e-6, true 3e-4 on the stairs), so convergence is judged on
  // W (b - A x) recomputed after every cycle.
  while (result.iterations < max_iterations) {
    const int before = result.iterations;
    const Eigen::VectorXd dx = gmres_cycle(a, wr, precondition, row_weight, inv_weight, rel_tol * beta,
                                           max_iterations - result.iterations, result);
    if (!dx.allFinite()) break;
    x += dx;
    wr = row_weight.cwiseProduct(b - a * x);
    result.relative_residual = wr.norm() / beta;
    if (result.relative_residual <= rel_tol) {
      result.converged = true;
      break;
    }
    if (result.iterations == before) break;  // no progress possible
  }
  return result;
}

}  // namespace fsi::solve
