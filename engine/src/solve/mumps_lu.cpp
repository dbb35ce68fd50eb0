#include "solve/mumps_lu.hpp"

#include <dmumps_c.h>

#include <cassert>
#include <cstring>
#include <mutex>

namespace fsi::solve {

namespace {
/// The sequential MUMPS keeps state of its own between and during calls (Fortran module
/// variables of its load balancing: two instances factorizing on two threads at once
/// crashed in DMUMPS_LOAD_INIT, MumpsLU.TheSameBitsFromEveryInstanceAndThread), so
/// every call into it holds this lock. The only state of fsi's outside an Engine: it
/// guards the library's. One engine calls MUMPS from its stepping thread only, so the lock
/// costs it nothing; engines stepping on several threads take turns in MUMPS.
std::mutex& mumps_lock() {
  static std::mutex m;
  return m;
}
}  // namespace

struct MumpsLU::Instance {
  DMUMPS_STRUC_C id{};
  int& icntl(int i) { return id.icntl[i - 1]; }
  double& cntl(int i) { return id.cntl[i - 1]; }
  int infog(int i) const { return id.infog[i - 1]; }
  void run(int job) {
    const std::lock_guard<std::mutex> lock(mumps_lock());
    id.job = job;
    dmumps_c(&id);
  }
  void set_controls();
};

namespace {

// MUMPS's use of MPI_COMM_WORLD in the sequential library's stub.
constexpr int kUseCommWorld = -987654;

// Error codes after which a factorization with more workspace succeeds (MUMPS user
// guide: -8, -9 workspace too small, -14, -15 the integer ones, -17, -20 buffers).
bool more_workspace_helps(int info1) {
  return info1 == -8 || info1 == -9 || info1 == -14 || info1 == -15 || info1 == -17 || info1 == -20;
}

}  // namespace

// The controls, numbered as in MUMPS's user guide (ICNTL(7) is icntl(7)).
void MumpsLU::Instance::set_controls() {
  Instance& m = *this;
  // No output at all: errors come back through INFOG(1).
  m.icntl(1) = -1;
  m.icntl(2) = -1;
  m.icntl(3) = -1;
  m.icntl(4) = 0;
  // AMF (approximate minimum fill): on the stairs' coupled blocks (43 307 unknowns) its
  // analysis takes 0.04 s against PORD's 0.21 s and METIS's 0.37 s, for a numeric
  // factorization of 0.25 s against PORD's 0.23 s and METIS's 0.32 s; a block's pattern
  // changes whenever the interface passes a node (a quarter of Example 1's
  // factorizations), so over 61 stairs steps in contact AMF took 0.88 of PORD's wall
  // time, and on Example 1 the two were even.
  m.icntl(7) = 2;
  // No column permutation for a zero-free diagonal and no analysis-time scaling: the
  // analysis then depends on the pattern alone, so a factorization rebuilt from a
  // checkpoint finds the same ordering whatever matrix was analysed first.
  m.icntl(6) = 0;
  // Row and column scaling by infinity norms, computed from the values of each
  // factorization (UMFPACK scales rows too).
  m.icntl(8) = 4;
  // Workspace: 30 % above the analysis's estimate (grown and retried when short).
  m.icntl(14) = 30;
  // Take a pivot unless it is below 1e-8 of its column within the front, as UMFPACK's
  // diagonal preference in solve/sparse_lu.cpp: a larger threshold delays pivots and
  // breaks the fill the ordering planned (1e-2: 2x the flops on Example 1).
  m.cntl(1) = 1e-8;
}

MumpsLU::MumpsLU() : mumps_(std::make_unique<Instance>()) {
  mumps_->id.comm_fortran = kUseCommWorld;
  mumps_->id.par = 1;  // the host works too (there is no other process)
  mumps_->id.sym = 0;  // unsymmetric
  mumps_->run(-1);     // initialize; sets the default controls
  mumps_->set_controls();
}

MumpsLU::~MumpsLU() { mumps_->run(-2); }

bool MumpsLU::analyze(const Matrix& a) {
  assert(a.isCompressed() && a.rows() == a.cols());
  const Eigen::Index n = a.rows(), nnz = a.nonZeros();
  const bool same_pattern = analysed_ && n == rows_ && nnz == inner_.size() &&
                            std::memcmp(outer_.data(), a.outerIndexPtr(), sizeof(int) * (n + 1)) == 0 &&
                            std::memcmp(inner_.data(), a.innerIndexPtr(), sizeof(int) * nnz) == 0;
  values_.assign(a.valuePtr(), a.valuePtr() + nnz);
  factorized_ = false;
  if (same_pattern) return true;
  rows_ = n;
  outer_ = Eigen::Map<const Eigen::VectorXi>(a.outerIndexPtr(), n + 1);
  inner_ = Eigen::Map<const Eigen::VectorXi>(a.innerIndexPtr(), nnz);
  row_index_.resize(nnz);
  column_index_.resize(nnz);
  for (Eigen::Index j = 0; j < n; ++j)
    for (int k = outer_[j]; k < outer_[j + 1]; ++k) {
      row_index_[k] = inner_[k] + 1;
      column_index_[k] = static_cast<int>(j) + 1;
    }
  DMUMPS_STRUC_C& id = mumps_->id;
  id.n = static_cast<MUMPS_INT>(n);
  id.nnz = nnz;
  id.irn = row_index_.data();
  id.jcn = column_index_.data();
  id.a = values_.data();
  mumps_->run(1);
  analysed_ = mumps_->infog(1) >= 0;
  if (analysed_) ++analyses_;
  return analysed_;
}

bool MumpsLU::factorize_analyzed() {
  if (!analysed_) return false;
  DMUMPS_STRUC_C& id = mumps_->id;
  id.irn = row_index_.data();
  id.jcn = column_index_.data();
  id.a = values_.data();
  // More workspace changes where MUMPS keeps the factors, not their values; it is kept
  // for the factorizations after this one.
  for (int attempt = 0; attempt < 4; ++attempt) {
    mumps_->run(2);
    if (!more_workspace_helps(mumps_->infog(1))) break;
    mumps_->icntl(14) *= 2;
  }
  factorized_ = mumps_->infog(1) >= 0;
  return factorized_;
}

Eigen::VectorXd MumpsLU::solve(const Eigen::VectorXd& b) const {
  assert(factorized_ && b.size() == rows_);
  Eigen::VectorXd x = b;  // MUMPS overwrites the right-hand side with the solution
  DMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = x.data();
  id.nrhs = 1;
  id.lrhs = static_cast<MUMPS_INT>(rows_);
  mumps_->run(3);
  id.rhs = nullptr;
  return x;
}

}  // namespace fsi::solve
