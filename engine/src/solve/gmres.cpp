#include "solve/gmres.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace fsi::solve {

namespace {

/// Iterations after which the observed convergence rate is trusted to predict the rest:
/// a preconditioned GMRES starts slowly and speeds up as the few eigenvalues the stale
/// factorization got wrong are resolved; on the stairs the rate settles after about ten
/// (Newton's first directions on 50 steps: no run that converged was predicted to fail).
constexpr int kIterationsBeforePredicting = 10;

/// One Arnoldi cycle of at most m iterations on W A M^-1 y = W b (b the current residual);
/// returns the correction Z y (Z the preconditioned basis vectors) and adds its
/// iterations to `result`. `scale` turns this cycle's residual into the whole solve's
/// relative one (this cycle's |W b| / the first's).
Eigen::VectorXd gmres_cycle(const SparseLU::Matrix& a, const Eigen::VectorXd& wb,
                            const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                            const Eigen::VectorXd& row_weight, const Eigen::VectorXd& inv_weight,
                            double rel_tol, double scale, int max_iterations, GmresResult& result) {
  const int m = max_iterations - result.iterations;
  const double beta = wb.norm();
  std::vector<Eigen::VectorXd> basis, preconditioned;
  basis.reserve(m + 1);
  preconditioned.reserve(m);
  basis.push_back(wb / beta);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);  // Hessenberg, rotated in place
  Eigen::VectorXd cs = Eigen::VectorXd::Zero(m), sn = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1);  // rotated right-hand side
  g[0] = beta;
  int k = 0;  // columns built
  for (; k < m; ++k) {
    // The correction is assembled from these very vectors (x = Z y, as in flexible GMRES)
    // rather than by one more solve of V y at the end: with an ill-conditioned stale
    // factorization M^-1 (V y) differs from (M^-1 V) y by far more than the tolerance,
    // and the true residual stalled at 1e-4 where the recurrence claimed 1e-6.
    preconditioned.push_back(precondition(inv_weight.cwiseProduct(basis[k])));
    Eigen::VectorXd w = row_weight.cwiseProduct(a * preconditioned[k]);
    if (!w.allFinite() || !preconditioned[k].allFinite()) {
      preconditioned.pop_back();
      break;
    }
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
    const double relative = std::abs(g[k + 1]) / beta * scale;
    const double next_norm = w.norm();
    if (relative <= rel_tol || !(next_norm > 0.0)) {
      ++k;
      break;
    }
    // Give up as soon as the rate so far says max_iterations will not do: the caller
    // then refactorizes, and every further iteration would be wasted.
    if (result.iterations >= kIterationsBeforePredicting &&
        (relative >= 1.0 ||
         result.iterations * std::log(rel_tol) / std::log(relative) > max_iterations)) {
      result.given_up = true;
      ++k;
      break;
    }
    basis.push_back(w / next_norm);
  }
  Eigen::VectorXd correction = Eigen::VectorXd::Zero(wb.size());
  if (k == 0) return correction;
  const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  for (int i = 0; i < k; ++i) correction += y[i] * preconditioned[i];
  return correction;
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
  // Restarted from the true residual: convergence is judged on W (b - A x) recomputed
  // after every cycle, never on the Arnoldi recurrence alone (rounding in the products
  // with an ill-conditioned preconditioned operator can make the two differ).
  while (result.iterations < max_iterations && !result.given_up) {
    const int before = result.iterations;
    const Eigen::VectorXd dx = gmres_cycle(a, wr, precondition, row_weight, inv_weight, rel_tol,
                                           wr.norm() / beta, max_iterations, result);
    if (!dx.allFinite()) break;
    x += dx;
    wr = row_weight.cwiseProduct(b - a * x);
    result.relative_residual = wr.norm() / beta;
    if (result.relative_residual <= rel_tol) {
      result.converged = true;
      result.given_up = false;
      break;
    }
    if (result.iterations == before) break;  // no progress possible
  }
  return result;
}

}  // namespace fsi::solve
