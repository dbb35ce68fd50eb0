#pragma once
/// \file sparse_lu.hpp
/// Sparse LU through UMFPACK with the symbolic analysis reused while the pattern stays.
///
/// The locally modified FE space keeps its DoFs and its sparsity pattern whatever the
/// interface does, so the fill-reducing ordering and symbolic analysis of the whole
/// Jacobian are computed once; the blocks of solve/split_lu.hpp change pattern when the
/// interface passes a node, and are analysed again then.
#include <Eigen/SparseCore>

namespace fsi::solve {

class SparseLU {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  SparseLU() = default;
  ~SparseLU();
  SparseLU(const SparseLU&) = delete;
  SparseLU& operator=(const SparseLU&) = delete;

  /// Numeric factorization of `a` (compressed). The first call, or a call with a
  /// different pattern (size / nonzero count), also runs the symbolic analysis.
  /// Returns false if UMFPACK reports a singular or failed factorization.
  bool factorize(const Matrix& a) { return analyze(a) && factorize_analyzed(); }
  /// The first half of factorize(): takes a copy of `a` and runs the symbolic analysis
  /// if its pattern is new. Returns false if the analysis fails.
  ///
  /// Not to be run on two threads at once, nor beside another METIS ordering: the METIS
  /// ordering inside is not safe for that (two SparseLUs analysed concurrently got other
  /// orderings, hence other bits, than analysed one after the other). Beside MUMPS's AMF
  /// analysis it is (SplitLU.TwoThreadsGiveTheSameBitsAsOne).
  bool analyze(const Matrix& a);
  /// The second half: the numeric factorization of the matrix analyze() took. Two
  /// SparseLUs may run this at the same time.
  bool factorize_analyzed();
  /// Solves A x = b with the last factorization. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// Reciprocal condition number estimate of the last factorization (UMFPACK's rcond).
  double rcond() const { return rcond_; }
  bool factorized() const { return numeric_ != nullptr; }
  int symbolic_analyses() const { return symbolic_count_; }

 private:
  void free_numeric();
  void free_symbolic();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  Eigen::Index rows_ = 0;
  Eigen::Index nonzeros_ = 0;
  // Copies of the pattern the factorization refers to (UMFPACK solves need them).
  Eigen::VectorXi outer_, inner_;
  Eigen::VectorXd values_;
  double rcond_ = 0.0;
  int symbolic_count_ = 0;
};

}  // namespace fsi::solve
