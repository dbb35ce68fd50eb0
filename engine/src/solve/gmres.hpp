#pragma once
/// \file gmres.hpp
/// GMRES with a right preconditioner: the Newton direction J dx = b from an *older* LU
/// factorization instead of a new one.
///
/// Why: on the stairs (71k unknowns) one UMFPACK factorization costs as much as about 80
/// solves with an existing one, and a step used to refactorize 1-3 times. The Jacobian of
/// the next iterate (or step) differs from the factorized one mostly near the moving
/// interface, so with the old LU as preconditioner, J M^-1 is the identity plus a
/// perturbation of small rank and norm, and GMRES needs a handful of iterations (one solve
/// and one product with J each) for a direction as exact as a new factorization's.
///
/// Right preconditioning keeps the minimized quantity the true residual |W (b - J x)|_2;
/// W is a diagonal row weight (Newton's row scale), so that the momentum, displacement and
/// pressure rows count alike. The solution is combined from the preconditioned vectors
/// themselves (as flexible GMRES does), and convergence is checked on the true residual
/// after each cycle (restarting from it if the recurrence was optimistic). GMRES gives up
/// early when its observed rate predicts no convergence within `max_iterations`: the
/// caller then refactorizes, which is cheaper than a long Krylov run.
#include <functional>

#include <Eigen/Core>

#include "solve/sparse_lu.hpp"

namespace fsi::solve {

struct GmresResult {
  bool converged = false;
  int iterations = 0;               ///< products with the matrix (= preconditioner solves)
  double relative_residual = 1.0;   ///< |W (b - A x)| / |W b| at the end
  /// Stopped before max_iterations because the rate so far predicted it would not converge.
  bool given_up = false;
};

/// Approximately solves A x = b: x = M^-1 V y with V the Krylov basis of (W A M^-1) and
/// y minimizing |W b - W A M^-1 V y|_2. `precondition(v)` applies M^-1 (e.g. an LU solve).
/// Stops when the weighted residual is at most rel_tol |W b|, after max_iterations, or as
/// soon as (after ten iterations) the rate so far predicts more than max_iterations.
GmresResult gmres(const SparseLU::Matrix& a, const Eigen::VectorXd& b,
                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                  const Eigen::VectorXd& row_weight, double rel_tol, int max_iterations,
                  Eigen::VectorXd& x);

}  // namespace fsi::solve
