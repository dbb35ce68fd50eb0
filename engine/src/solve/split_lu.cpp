#include "solve/split_lu.hpp"

#include <cassert>
#include <cstring>
#include <thread>

namespace fsi::solve {
namespace {

/// An empty compressed rows x cols matrix with room for `nonzeros` entries, to be filled
/// column by column through its raw arrays.
void shape(SparseLU::Matrix& m, Eigen::Index rows, Eigen::Index cols, Eigen::Index nonzeros) {
  m.resize(rows, cols);
  m.makeCompressed();
  m.resizeNonZeros(nonzeros);
}

bool same_pattern(const SparseLU::Matrix& a, const Eigen::VectorXi& outer, const Eigen::VectorXi& inner) {
  return outer.size() == a.cols() + 1 && inner.size() == a.nonZeros() &&
         std::memcmp(outer.data(), a.outerIndexPtr(), sizeof(int) * outer.size()) == 0 &&
         std::memcmp(inner.data(), a.innerIndexPtr(), sizeof(int) * inner.size()) == 0;
}

}  // namespace

void SplitLU::index_blocks(const Matrix& a, const std::vector<char>& extension) {
  const int n = static_cast<int>(a.rows());
  partition_ = extension;
  pattern_outer_ = Eigen::Map<const Eigen::VectorXi>(a.outerIndexPtr(), a.cols() + 1);
  pattern_inner_ = Eigen::Map<const Eigen::VectorXi>(a.innerIndexPtr(), a.nonZeros());
  coupled_rows_.clear();
  extension_rows_.clear();
  std::vector<int> local(n);
  for (int i = 0; i < n; ++i) {
    std::vector<int>& block = extension[i] ? extension_rows_ : coupled_rows_;
    local[i] = static_cast<int>(block.size());
    block.push_back(i);
  }
  // Count, then fill: columns and rows keep their order within a block, so each block's
  // columns come out sorted as a's are.
  Eigen::Index nnz_cc = 0, nnz_ee = 0, nnz_ec = 0;
  for (int j = 0; j < n; ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const bool row_ext = extension[a.innerIndexPtr()[k]], col_ext = extension[j];
      nnz_cc += !row_ext && !col_ext;
      nnz_ee += row_ext && col_ext;
      nnz_ec += row_ext && !col_ext;
    }
  const Eigen::Index nc = static_cast<Eigen::Index>(coupled_rows_.size());
  const Eigen::Index ne = static_cast<Eigen::Index>(extension_rows_.size());
  shape(a_cc_, nc, nc, nnz_cc);
  shape(a_ee_, ne, ne, nnz_ee);
  shape(a_ec_, ne, nc, nnz_ec);
  from_cc_.resize(nnz_cc);
  from_ee_.resize(nnz_ee);
  from_ec_.resize(nnz_ec);
  ce_entries_.clear();
  int cc = 0, ee = 0, ec = 0;
  for (int j = 0; j < n; ++j) {
    if (extension[j]) {
      a_ee_.outerIndexPtr()[local[j]] = ee;
    } else {
      a_cc_.outerIndexPtr()[local[j]] = cc;
      a_ec_.outerIndexPtr()[local[j]] = ec;
    }
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (extension[j] && extension[i]) {
        a_ee_.innerIndexPtr()[ee] = local[i];
        from_ee_[ee++] = k;
      } else if (extension[j]) {
        ce_entries_.push_back(k);
      } else if (extension[i]) {
        a_ec_.innerIndexPtr()[ec] = local[i];
        from_ec_[ec++] = k;
      } else {
        a_cc_.innerIndexPtr()[cc] = local[i];
        from_cc_[cc++] = k;
      }
    }
  }
  a_cc_.outerIndexPtr()[nc] = cc;
  a_ee_.outerIndexPtr()[ne] = ee;
  a_ec_.outerIndexPtr()[nc] = ec;
}

bool SplitLU::gather_values(const Matrix& a) {
  const double* v = a.valuePtr();
  for (int k : ce_entries_)
    if (v[k] != 0.0) return false;
  for (std::size_t k = 0; k < from_cc_.size(); ++k) a_cc_.valuePtr()[k] = v[from_cc_[k]];
  for (std::size_t k = 0; k < from_ee_.size(); ++k) a_ee_.valuePtr()[k] = v[from_ee_[k]];
  for (std::size_t k = 0; k < from_ec_.size(); ++k) a_ec_.valuePtr()[k] = v[from_ec_[k]];
  return true;
}

bool SplitLU::factorize(const Matrix& a, const std::vector<char>& extension, int threads) {
  assert(a.isCompressed() && a.rows() == a.cols());
  bool any_extension = false;
  if (static_cast<Eigen::Index>(extension.size()) == a.rows())
    for (char e : extension) any_extension = any_extension || e != 0;
  split_ = false;
  if (any_extension) {
    if (extension != partition_ || !same_pattern(a, pattern_outer_, pattern_inner_)) index_blocks(a, extension);
    split_ = gather_values(a);
  }
  if (!split_) return whole_.factorize(a);
  if (threads < 2) {
    const bool coupled_ok = coupled_.factorize(a_cc_);
    return coupled_ok && extension_.factorize(a_ee_);
  }
  // The extension block is the smaller one (on Example 1 7917 unknowns against 13208,
  // 0.016-0.02 s of UMFPACK against 0.047-0.065 s of MUMPS for the coupled block): it
  // finishes while the coupled block is still being factorized, and the two LUs share
  // nothing (each library keeps its state in its own objects; OpenBLAS serializes
  // nothing at one thread per call). MUMPS stays on this thread.
  // The extension block's analysis (where its pattern is new) goes to the worker too:
  // UMFPACK's METIS ordering there meets no other METIS call, since MUMPS orders the
  // coupled block by AMF (two METIS orderings at once, in two SparseLUs, gave other
  // orderings: SparseLU::analyze). Near the ground, where the patterns change often,
  // the two analyses took 9 and 12 ms per factorization against the coupled block's 62 ms
  // (Example 1, t = 2.2 to 2.4 s, 121 factorizations).
  bool extension_ok = false;
  std::thread worker([&] { extension_ok = extension_.analyze(a_ee_) && extension_.factorize_analyzed(); });
  const bool coupled_ok = coupled_.analyze(a_cc_) && coupled_.factorize_analyzed();
  worker.join();
  return coupled_ok && extension_ok;
}

Eigen::VectorXd SplitLU::solve(const Eigen::VectorXd& b) const {
  if (!split_) return whole_.solve(b);
  const Eigen::Index nc = a_cc_.rows(), ne = a_ee_.rows();
  Eigen::VectorXd bc(nc), be(ne);
  for (Eigen::Index i = 0; i < nc; ++i) bc[i] = b[coupled_rows_[i]];
  for (Eigen::Index i = 0; i < ne; ++i) be[i] = b[extension_rows_[i]];
  const Eigen::VectorXd xc = coupled_.solve(bc);
  be.noalias() -= a_ec_ * xc;
  const Eigen::VectorXd xe = extension_.solve(be);
  Eigen::VectorXd x(b.size());
  for (Eigen::Index i = 0; i < nc; ++i) x[coupled_rows_[i]] = xc[i];
  for (Eigen::Index i = 0; i < ne; ++i) x[extension_rows_[i]] = xe[i];
  return x;
}

}  // namespace fsi::solve
