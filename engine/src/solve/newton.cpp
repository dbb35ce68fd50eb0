#include "solve/newton.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "solve/gmres.hpp"

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

void NewtonSolver::assemble_jacobian(const core::FsiSystem& system, const Eigen::VectorXd& x,
                                     Eigen::VectorXd& r, NewtonResult& result) {
  const auto t0 = std::chrono::steady_clock::now();
  system.residual_and_jacobian(x, r, jacobian_);
  result.assembly_seconds += seconds_since(t0);
  ++result.jacobians;
}

void NewtonSolver::scale_rows_by_jacobian() {
  // Row scaling for the residual norm: 1 / max_j |J_ij|.
  row_scale_.setZero(jacobian_.rows());
  for (int c = 0; c < jacobian_.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(jacobian_, c); it; ++it)
      row_scale_[it.row()] = std::max(row_scale_[it.row()], std::abs(it.value()));
  for (int i = 0; i < row_scale_.size(); ++i) row_scale_[i] = row_scale_[i] > 0.0 ? 1.0 / row_scale_[i] : 1.0;
}

bool NewtonSolver::factorize_assembled(const Eigen::VectorXd& x, NewtonResult& result) {
  if (!jacobian_.coeffs().allFinite()) {
    result.non_finite = true;
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool ok = lu_->factorize(jacobian_, extension_, lu_threads_);
  result.factorization_seconds += seconds_since(t0);
  ++result.factorizations;
  result.factorization_point = x;
  if (!ok) result.singular = true;
  return ok;
}

bool NewtonSolver::refactorize(const core::FsiSystem& system, const Eigen::VectorXd& x,
                               Eigen::VectorXd& r, NewtonResult& result) {
  assemble_jacobian(system, x, r, result);
  scale_rows_by_jacobian();
  return factorize_assembled(x, result);
}

bool NewtonSolver::factorize_at(const core::FsiSystem& system, const Eigen::VectorXd& x) {
  NewtonResult ignored;
  Eigen::VectorXd r;
  system.extension_unknowns(extension_);  // of this geometry, as solve() takes them
  return refactorize(system, x, r, ignored);
}

int NewtonSolver::krylov_direction(const Eigen::VectorXd& r, double rel_tol, const NewtonOptions& options,
                                   NewtonResult& result, Eigen::VectorXd& dx) {
  if (!jacobian_.coeffs().allFinite()) return -1;
  const auto t0 = std::chrono::steady_clock::now();
  const GmresResult g = gmres(
      jacobian_, -r, [this](const Eigen::VectorXd& v) { return lu_->solve(v); }, row_scale_, rel_tol,
      options.krylov_max_iterations, dx);
  result.solve_seconds += seconds_since(t0);
  result.krylov_iterations += g.iterations;
  return g.converged ? g.iterations : -1;
}

NewtonResult NewtonSolver::solve(const core::FsiSystem& system, Eigen::VectorXd& x,
                                 const NewtonOptions& options) {
  NewtonResult result;
  Eigen::VectorXd r, r_try, x_try;
  const bool krylov = options.krylov_max_iterations > 0;
  lu_threads_ = options.lu_threads;
  system.extension_unknowns(extension_);
  bool fresh = false;         // the factorization held was built at the current iterate
  bool own_lu = false;        // ... or at least in this call (not at another step's geometry)
  bool jacobian_at_x = false; // jacobian_ holds the Jacobian at the current iterate
  if (!lu_->factorized() || (!options.reuse_across_steps && !krylov)) {
    if (!refactorize(system, x, r, result)) return result;
    fresh = own_lu = jacobian_at_x = true;
  } else if (krylov) {
    // With GMRES the first direction is the exact one, and the norm's row scale is the
    // Jacobian of this step's start: a function of the state alone, so that a state
    // restored from a checkpoint goes on bit for bit (only the factorization is restored).
    assemble_jacobian(system, x, r, result);
    scale_rows_by_jacobian();
    jacobian_at_x = true;
  } else {
    const auto t0 = std::chrono::steady_clock::now();
    system.residual(x, r);
    result.assembly_seconds += seconds_since(t0);
  }
  double current = norm(r);
  // Solid points the iterate has inverted (det(I - grad u) <= 0): no update may add any.
  int inverted = system.inverted_solid_points(x);
  result.norms.push_back(current);
  if (!std::isfinite(current)) {
    result.non_finite = true;
    return result;
  }
  // The tolerance is relative to the step's initial residual measured with the row scale
  // in use. A factorization reused from an earlier step carries that step's row scale,
  // which on a changed cut can be off by orders of magnitude (a sliver sub-element's tiny
  // row becomes a normal one); every new row scale (a refactorization, or with GMRES any
  // new Jacobian) therefore re-measures the initial residual. Otherwise a step would
  // "converge" six orders of magnitude short of the others.
  const Eigen::VectorXd r_start = r;
  double tol = std::max(options.rel_tol * current, options.abs_tol);
  const auto rescale_tolerance = [&] { tol = std::max(options.rel_tol * norm(r_start), options.abs_tol); };
  if (current <= options.abs_tol) {
    result.converged = true;
    return result;
  }
  // Chord steps (the factorization held, without a new Jacobian) only with a factorization
  // of this step: one of another step's geometry throws the first iterate off by orders
  // of magnitude (1e4 -> 1e10 on the stairs) and wastes the iteration.
  bool need_exact = krylov && !own_lu;
  for (int it = 0; it < options.budget; ++it) {
    ++result.iterations;
    // The direction: a chord step while the factorization contracts well; otherwise the
    // Jacobian at x, solved by GMRES on the factorization held (krylov_max_iterations > 0)
    // or by refactorizing at x (also when GMRES does not converge).
    Eigen::VectorXd dx;
    bool exact = fresh;  // dx solves the Jacobian at x (not a chord step)
    if (need_exact && !fresh) {
      if (krylov) {
        if (!jacobian_at_x) {
          assemble_jacobian(system, x, r, result);
          scale_rows_by_jacobian();
          current = norm(r);
          rescale_tolerance();
          jacobian_at_x = true;
        }
        // GMRES only as far as Newton can use it: the linear residual a little below what
        // the tolerance asks of this iteration (Eisenstat and Walker's inexact Newton),
        // never looser than 1e-2 nor tighter than krylov_rel_tol.
        const double eta = std::clamp(0.1 * tol / current, options.krylov_rel_tol, 1e-2);
        const int used = krylov_direction(r, eta, options, result, dx);
        if (used >= 0) {
          exact = true;
          // A preconditioner that needs many iterations is stale (another step's
          // geometry): a factorization here costs about 50 GMRES iterations and brings
          // the next directions, of this step and the following ones, down to a few.
          if (2 * used > options.krylov_max_iterations) {
            if (!factorize_assembled(x, result)) break;
            fresh = own_lu = true;
          }
        } else {
          dx.resize(0);
          if (!factorize_assembled(x, result)) break;
          fresh = own_lu = exact = true;
        }
      } else {
        if (!refactorize(system, x, r, result)) break;
        current = norm(r);
        rescale_tolerance();
        fresh = own_lu = exact = jacobian_at_x = true;
      }
    }
    auto t0 = std::chrono::steady_clock::now();
    if (dx.size() == 0) dx = -lu_->solve(r);
    result.solve_seconds += seconds_since(t0);
    double lambda = 1.0, trial = 0.0;
    int inverted_try = inverted;
    bool decrease = false;
    // A chord step (the factorization of an earlier iterate, often of the previous step's
    // cut) is taken only if it contracts the residual by reuse_contraction, at full length.
    // One that merely decreases it can land far from the solution: at Example 1's film
    // formation (t = 2.334 s) the previous step's factorization took 61.6 -> 51.7, and
    // from there Newton with exact Jacobians crawled (6e-3, 4.4e-3, 4.1e-3, 1.2e-3) and
    // stopped, while exact Newton from the step's start converges in three iterations
    // (109.7 -> 7e-4 -> 1.4e-8 in the step's own row scale). Refused, the chord step costs
    // one residual evaluation.
    const double required = exact ? 1.0 : options.reuse_contraction;
    const int halvings = exact ? 4 : 1;
    for (int halving = 0; halving < halvings; ++halving, lambda *= 0.5) {
      x_try = x + lambda * dx;
      // An update that turns the solid inside out is refused before its residual is
      // even computed: its residual may well be smaller (soft ball: 1.2e4 -> 6.2e3 with
      // 38 points inverted), but from there Newton stalls on a singular Jacobian.
      inverted_try = system.inverted_solid_points(x_try);
      if (inverted_try > inverted) continue;
      t0 = std::chrono::steady_clock::now();
      system.residual(x_try, r_try);
      result.assembly_seconds += seconds_since(t0);
      trial = norm(r_try);
      decrease = trial < required * current;
      if (decrease) break;
    }
    if (!decrease) {
      // Even the exact Jacobian does not help: give up.
      if (exact) break;
      // A refused chord step: take the Jacobian at x and try again. It does not count
      // against the budget (it cost one residual evaluation, and the budget bounds the
      // iterations that cost a solve with a new Jacobian or move the iterate); the next
      // direction is exact, so at most every other direction can be refused.
      need_exact = true;
      --it;
      --result.iterations;
      continue;
    }
    // Keep the factorization while it contracts well enough *and* fast enough to reach
    // the tolerance within the remaining budget at the observed rate.
    const double rate = trial / current;
    const int remaining = options.budget - it - 1;
    need_exact = rate > options.reuse_contraction ||
                 (trial > tol && !exact && trial * std::pow(rate, remaining) > tol) || (krylov && !own_lu);
    x.swap(x_try);
    r.swap(r_try);
    ++result.accepted_iterates;
    current = trial;
    inverted = inverted_try;
    fresh = jacobian_at_x = false;
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
