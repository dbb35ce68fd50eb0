#include "solve/sparse_lu.hpp"

#include <umfpack.h>

#include <cassert>
#include <cstring>

namespace fsi::solve {

SparseLU::~SparseLU() {
  free_numeric();
  free_symbolic();
}

void SparseLU::free_numeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void SparseLU::free_symbolic() {
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

namespace {

/// UMFPACK's controls for the FSI Jacobians (the same for the analysis and the numeric
/// factorization).
void set_controls(double* control) {
  umfpack_di_defaults(control);
  // Nested dissection (METIS through CHOLMOD) suits the 2D grid graph: on the 4225-node
  // FSI pattern it needs 2.3x fewer flops than the default AMD ordering.
  control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  // The symmetric strategy (METIS on A+A^T, diagonal pivots preferred) is what UMFPACK's
  // automatic choice picks for these Jacobians; stating it keeps that choice fixed. The
  // unsymmetric one needs 1.7x the flops (1.53G vs 0.90G on Example 1's Jacobian).
  control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  // Take the diagonal entry as pivot unless it is below 1e-8 of its column's largest
  // (after UMFPACK's row scaling) instead of below 1e-3 (the default). On Example 1's
  // Jacobians (4225 nodes) the default rejected 275-320 diagonal pivots; each off-diagonal
  // pivot breaks the fill pattern METIS planned for. With 1e-8 none is rejected: 0.65G
  // instead of 0.90G flops, 3.67M instead of 4.12M entries in L+U, a numeric factorization
  // 15-20 % cheaper (1.25-1.36 instead of 1.50-1.60 reference factorizations, UMFPACK
  // alone on the saved Jacobians, glibc keeping large blocks in the heap), and no less
  // accurate: for x = A^-1 (A x_true), max|x - x_true| / max|x_true| 1.1e-7 to 6.6e-7
  // against 5.6e-7 to 1.7e-6, residual 7e-16 to 1e-15 against 6e-15 to 2e-14, UMFPACK's
  // rcond estimate 100x larger. (1e-4 still rejected ~150 pivots, 1e-6 ~65.)
  control[UMFPACK_SYM_PIVOT_TOLERANCE] = 1e-8;
}

}  // namespace

bool SparseLU::analyze(const Matrix& a) {
  assert(a.isCompressed() && a.rows() == a.cols());
  // Same pattern = same column pointers AND same row indices (equal column counts alone
  // do not make the symbolic analysis reusable).
  const bool same_pattern = symbolic_ && a.rows() == rows_ && a.nonZeros() == nonzeros_ &&
                            std::memcmp(outer_.data(), a.outerIndexPtr(),
                                        sizeof(int) * (a.rows() + 1)) == 0 &&
                            std::memcmp(inner_.data(), a.innerIndexPtr(),
                                        sizeof(int) * a.nonZeros()) == 0;
  rows_ = a.rows();
  nonzeros_ = a.nonZeros();
  outer_ = Eigen::Map<const Eigen::VectorXi>(a.outerIndexPtr(), rows_ + 1);
  inner_ = Eigen::Map<const Eigen::VectorXi>(a.innerIndexPtr(), nonzeros_);
  values_ = Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), nonzeros_);

  free_numeric();
  if (same_pattern) return true;
  free_symbolic();
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  set_controls(control);
  const int status = umfpack_di_symbolic(static_cast<int>(rows_), static_cast<int>(rows_), outer_.data(),
                                         inner_.data(), values_.data(), &symbolic_, control, info);
  if (status != UMFPACK_OK) {
    free_symbolic();
    return false;
  }
  ++symbolic_count_;
  return true;
}

bool SparseLU::factorize_analyzed() {
  if (!symbolic_) return false;
  free_numeric();
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  set_controls(control);
  const int status = umfpack_di_numeric(outer_.data(), inner_.data(), values_.data(), symbolic_,
                                        &numeric_, control, info);
  rcond_ = info[UMFPACK_RCOND];
  if (status != UMFPACK_OK) {  // includes UMFPACK_WARNING_singular_matrix
    free_numeric();
    return false;
  }
  return true;
}

Eigen::VectorXd SparseLU::solve(const Eigen::VectorXd& b) const {
  assert(numeric_ && b.size() == rows_);
  Eigen::VectorXd x(rows_);
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  umfpack_di_defaults(control);
  // No iterative refinement: Newton corrects the solution anyway, and each refinement
  // step costs another full forward/backward solve.
  control[UMFPACK_IRSTEP] = 0;
  umfpack_di_solve(UMFPACK_A, outer_.data(), inner_.data(), values_.data(), x.data(), b.data(),
                   numeric_, control, info);
  return x;
}

}  // namespace fsi::solve
