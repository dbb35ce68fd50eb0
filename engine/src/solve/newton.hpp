#pragma once
/// \file newton.hpp
/// Newton's method with a fixed iteration budget, so that one time step has a bounded
/// cost, and a reused LU factorization.
///
/// The Jacobian is exact (automatic differentiation), but factorizing it is the most
/// expensive stage of a step (0.1-0.3 s on 4225 nodes, 0.6-1.8 s on 16641). The
/// factorization is therefore kept across iterations and time steps while it still
/// contracts the residual by `reuse_contraction` per iteration; when it does not, the
/// Jacobian is re-assembled at the current iterate and refactorized. A backtracking
/// line search (up to 3 halvings) guards against overshooting and never accepts an
/// update that inverts more of the solid (FsiSystem::inverted_solid_points).
///
/// Residual norm: max_i |R_i| / max_j |J_ij| (rows scaled by the Jacobian of the last
/// factorization): comparable across the velocity, displacement and pressure rows. The
/// relative tolerance is re-based whenever the scale changes (see solve()).
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/fsi_system.hpp"
#include "solve/split_lu.hpp"

namespace fsi::solve {

struct NewtonOptions {
  int budget = 8;
  double rel_tol = 1e-8;
  double abs_tol = 1e-10;
  double reuse_contraction = 0.2;
  /// Whether a factorization of an earlier step may serve this step's first chord steps.
  /// false: the step factorizes at its start (the engine's choice in real contact). With
  /// GMRES (krylov_max_iterations > 0) every step starts from its own Jacobian anyway.
  bool reuse_across_steps = true;
  /// > 0: where a new Jacobian is needed, solve it by GMRES preconditioned with the
  /// factorization held, up to this many iterations, and refactorize only if that fails
  /// (solve/gmres.hpp). 0: refactorize.
  int krylov_max_iterations = 0;
  /// The tightest GMRES tolerance (relative to the weighted residual it starts from);
  /// each iteration asks only for what reaches Newton's tolerance, up to 1e-2.
  double krylov_rel_tol = 1e-6;
  /// Threads of the factorization (SplitLU::factorize: >= 2 factorizes its two blocks at
  /// the same time). The factors, and so every iterate, are the same bits for any count.
  int lu_threads = 1;
};

struct NewtonResult {
  bool converged = false;
  bool non_finite = false;
  bool singular = false;
  int iterations = 0;
  /// Iterates the line search accepted (0: x is still the start, nothing was solved).
  int accepted_iterates = 0;
  int factorizations = 0;
  int jacobians = 0;          ///< Jacobian assemblies (for a factorization or for GMRES)
  int krylov_iterations = 0;  ///< GMRES iterations (one solve with the factorization each)
  std::vector<double> norms;  ///< scaled residual norm before each iteration and at the end
  /// The final residual over the step's first one, both measured with the row scale of the
  /// last factorization (norms.back() / norms.front() may mix two scales).
  double relative_residual = 1.0;
  /// The row of the largest scaled final residual (-1: none measured) and that value, in
  /// the row scale of the last factorization.
  Eigen::Index worst_row = -1;
  double worst_value = 0.0;
  double assembly_seconds = 0.0, factorization_seconds = 0.0, solve_seconds = 0.0;
  /// The iterate of the last factorization of this call (empty: none happened).
  Eigen::VectorXd factorization_point;
};

class NewtonSolver {
 public:
  explicit NewtonSolver(const SparseMatrix& pattern) : jacobian_(pattern) {}
  /// Solves R(x) = 0 starting from x (updated in place).
  NewtonResult solve(const core::FsiSystem& system, Eigen::VectorXd& x, const NewtonOptions& options);
  /// Forget the factorization.
  void reset() { lu_ = std::make_unique<SplitLU>(); }
  /// Assembles the Jacobian at x and factorizes it (used to restore a saved state's
  /// factorization exactly). Returns false if it is singular or not finite.
  bool factorize_at(const core::FsiSystem& system, const Eigen::VectorXd& x);

 private:
  double norm(const Eigen::VectorXd& r) const;
  bool refactorize(const core::FsiSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& r,
                   NewtonResult& result);
  void assemble_jacobian(const core::FsiSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& r,
                         NewtonResult& result);
  /// The norm's row scale from the Jacobian last assembled.
  void scale_rows_by_jacobian();
  /// Factorizes the Jacobian last assembled (at x).
  bool factorize_assembled(const Eigen::VectorXd& x, NewtonResult& result);
  /// The Newton direction for the Jacobian last assembled, by GMRES on the held
  /// factorization to rel_tol; returns the GMRES iterations, -1 if it did not converge.
  int krylov_direction(const Eigen::VectorXd& r, double rel_tol, const NewtonOptions& options,
                       NewtonResult& result, Eigen::VectorXd& dx);

  SparseMatrix jacobian_;
  std::unique_ptr<SplitLU> lu_ = std::make_unique<SplitLU>();
  std::vector<char> extension_;  ///< the system's extension unknowns (SplitLU)
  Eigen::VectorXd row_scale_;
  int lu_threads_ = 1;  ///< NewtonOptions::lu_threads of the latest solve()
};

}  // namespace fsi::solve
