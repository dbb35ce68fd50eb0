#include "solve/newton.hpp"

#include <chrono>
#include <cmath>

namespace fsi::solve {
namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

double NewtonSolver::norm(const Eigen::VectorXd& r) const {
  if (!r.allFinite()) return std::numeric_limits<double>::infinity();
  return row_scale_.size() == r.size() ? r.cwiseProduct(row_scale_).cwiseAbs().maxCoeff()
                                       : r.cwiseAbs().maxCoeff();
}

bool NewtonSolver::refactorize(const core::FsiSystem& system, const Eigen::VectorXd& x,
                               Eigen::VectorXd& r, NewtonResult& result) {
  auto t0 = std::chrono::steady_clock::now();
  system.residual_and_jacobian(x, r, jacobian_);
  result.assembly_seconds += seconds_since(t0);
  // Row scaling for the residual norm: 1 / max_j |J_ij|.
  row_scale_.setZero(jacobian_.rows());
  for (int c = 0; c < jacobian_.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(jacobian_, c); it; ++it)
      row_scale_[it.row()] = std::max(row_scale_[it.row()], std::abs(it.value()));
  for (int i = 0; i < row_scale_.size(); ++i) row_scale_[i] = row_scale_[i] > 0.0 ? 1.0 / row_scale_[i] : 1.0;
  if (!jacobian_.coeffs().allFinite()) {
    result.non_finite = true;
    return false;
  }
  t0 = std::chrono::steady_clock::now();
  const bool ok = lu_->factorize(jacobian_);
  result.factorization_seconds += seconds_since(t0);
  ++result.factorizations;
  result.factorization_point = x;
  if (!ok) result.singular = true;
  return ok;
}

bool NewtonSolver::factorize_at(const core::FsiSystem& system, const Eigen::VectorXd& x) {
  NewtonResult ignored;
  Eigen::VectorXd r;
  return refactorize(system, x, r, ignored);
}

NewtonResult NewtonSolver::solve(const core::FsiSystem& system, Eigen::VectorXd& x,
                                 const NewtonOptions& options) {
  NewtonResult result;
  Eigen::VectorXd r, r_try, x_try;
  bool fresh = false;  // factorization built at the current iterate
  if (!lu_->factorized()) {
    if (!refactorize(system, x, r, result)) return result;
    fresh = true;
  } else {
    const auto t0 = std::chrono::steady_clock::now();
    system.residual(x, r);
    result.assembly_seconds += seconds_since(t0);
  }
  double current = norm(r);
  result.norms.push_back(current);
  if (!std::isfinite(current)) {
    result.non_finite = true;
    return result;
  }
  // The tolerance is relative to the step's initial residual measured with the row scale
  // of the factorization in use. A factorization reused from an earlier step carries that
  // step's row scale, which on a changed cut can be off by orders of magnitude (a sliver
  // sub-element's tiny row becomes a normal one); every refactorization therefore
  // re-measures the initial residual with the new scale. Otherwise a step would "converge"
  // six orders of magnitude short of the others.
  const Eigen::VectorXd r_start = r;
  double tol = std::max(options.rel_tol * current, options.abs_tol);
  const auto rescale_tolerance = [&] { tol = std::max(options.rel_tol * norm(r_start), options.abs_tol); };
  if (current <= options.abs_tol) {
    result.converged = true;
    return result;
  }
  bool need_refactor = false;
  for (int it = 0; it < options.budget; ++it) {
    ++result.iterations;
    if (need_refactor && !fresh) {
      if (!refactorize(system, x, r, result)) break;
      current = norm(r);
      rescale_tolerance();
      fresh = true;
    }
    auto t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd dx = -lu_->solve(r);
    result.solve_seconds += seconds_since(t0);
    double lambda = 1.0, trial = 0.0;
    for (int halving = 0; halving < 4; ++halving, lambda *= 0.5) {
      x_try = x + lambda * dx;
      t0 = std::chrono::steady_clock::now();
      system.residual(x_try, r_try);
      result.assembly_seconds += seconds_since(t0);
      trial = norm(r_try);
      if (trial < current) break;
    }
    if (!(trial < current)) {
      // No decrease along this direction: with a stale factorization, refactorize and
      // try again (the iteration still counts against the budget).
      need_refactor = true;
      if (fresh) break;  // even the exact Jacobian does not help: give up
      continue;
    }
    // Keep the factorization while it contracts well enough *and* fast enough to reach
    // the tolerance within the remaining budget at the observed rate.
    const double rate = trial / current;
    const int remaining = options.budget - it - 1;
    need_refactor = rate > options.reuse_contraction ||
                    (trial > tol && !fresh && trial * std::pow(rate, remaining) > tol);
    x.swap(x_try);
    r.swap(r_try);
    ++result.accepted_iterates;
    current = trial;
    fresh = false;
    result.norms.push_back(current);
    if (current <= tol) {
      result.converged = true;
      break;
    }
  }
  result.non_finite = !x.allFinite();
  const double start = norm(r_start);
  result.relative_residual = start > 0.0 ? current / start : 0.0;
  if (r.size() > 0 && r.allFinite()) {
    const Eigen::VectorXd scaled =
        row_scale_.size() == r.size() ? Eigen::VectorXd(r.cwiseProduct(row_scale_)) : r;
    result.worst_value = scaled.cwiseAbs().maxCoeff(&result.worst_row);
  }
  return result;
}

}  // namespace fsi::solve
