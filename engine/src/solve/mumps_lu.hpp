#pragma once
/// \file mumps_lu.hpp
/// Sparse LU through the sequential MUMPS (multifrontal), with the analysis reused while
/// the pattern stays: the factorization of the coupled block (solve/split_lu.hpp).
///
/// Why MUMPS there and not UMFPACK: on the coupled blocks of Example 1 (13 208 unknowns)
/// MUMPS's numeric factorization takes 0.045-0.065 s where UMFPACK (METIS, symmetric
/// strategy) takes 0.084-0.092 s, and on the stairs' (43 307 unknowns) 0.25 s against
/// 0.41 s, with solutions as accurate (the residual of A x = b 1e-7..6e-7 relative against
/// UMFPACK's 6e-7..7e-7), measured on saved Jacobians in one process; whole runs in
/// docs/solver.md, "Cost of a step". UMFPACK stays for the extension block, whose solves
/// it does in 0.6 ms against MUMPS's 1.6 ms.
///
/// Deterministic: the ordering (AMF) and the symbolic factorization depend on the
/// pattern alone, the scaling is computed from the values in each factorization, and the
/// sequential MUMPS runs on one thread (BLAS threads as OPENBLAS_NUM_THREADS says).
/// MUMPS is not reentrant, so every call into it takes a process-wide lock (mumps_lu.cpp):
/// MumpsLUs on several threads are safe and take turns. SplitLU runs MUMPS on the calling
/// thread only and UMFPACK beside it.
#include <memory>
#include <vector>

#include "solve/sparse_lu.hpp"

namespace fsi::solve {

class MumpsLU {
 public:
  using Matrix = SparseLU::Matrix;

  MumpsLU();
  ~MumpsLU();
  MumpsLU(const MumpsLU&) = delete;
  MumpsLU& operator=(const MumpsLU&) = delete;

  /// Numeric factorization of `a` (compressed, square); the analysis runs when the
  /// pattern is new. Returns false if MUMPS reports a singular or failed factorization.
  bool factorize(const Matrix& a) { return analyze(a) && factorize_analyzed(); }
  /// Takes a copy of `a` and runs the analysis (ordering, symbolic factorization) if its
  /// pattern differs from the last one analysed. Returns false if the analysis fails.
  bool analyze(const Matrix& a);
  /// The numeric factorization of the matrix analyze() took.
  bool factorize_analyzed();
  /// Solves A x = b with the last factorization. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  bool factorized() const { return factorized_; }
  int symbolic_analyses() const { return analyses_; }

 private:
  struct Instance;  // MUMPS's control structure (keeps dmumps_c.h out of this header)
  std::unique_ptr<Instance> mumps_;
  bool analysed_ = false;
  bool factorized_ = false;
  int analyses_ = 0;
  Eigen::Index rows_ = 0;
  // The pattern analysed (for the comparison) and MUMPS's 1-based coordinates of it;
  // MUMPS reads the coordinates again in every factorization.
  Eigen::VectorXi outer_, inner_;
  std::vector<int> row_index_, column_index_;
  std::vector<double> values_;
};

}  // namespace fsi::solve
