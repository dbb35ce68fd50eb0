#pragma once
/// \file split_lu.hpp
/// The FSI Jacobian's LU in two blocks: the coupled unknowns first, the extensions after.
///
/// Two kinds of rows only continue a field where its equation does not live: the
/// displacement of a node that touches no solid sub-element (the fluid's harmonic
/// extension of u) and the pressure of a node that touches no fluid sub-element (the
/// solid's extension of p). No other row depends on those unknowns: the fluid's momentum
/// and divergence see v and p at fluid-touching nodes only, the solid's equations v and u
/// at solid-touching nodes only, and the pressure stabilization couples fluid cells only
/// (forms/fsi_element.hpp, forms/pressure_stabilization.hpp). With the unknowns ordered
/// "coupled" (c) then "extension" (e) the Jacobian is block lower triangular,
///
///   [A_cc  0   ] [x_c]   [b_c]
///   [A_ec  A_ee] [x_e] = [b_e],   x_c = A_cc^-1 b_c,  x_e = A_ee^-1 (b_e - A_ec x_c),
///
/// and two LUs of the diagonal blocks replace the LU of the whole: on Example 1 the
/// coupled block has about 3 unknowns per fluid node instead of 5 (measured in
/// docs/solver.md, "Cost of a step"). The solution is that of the whole system, to
/// round-off.
///
/// The zero block is checked, not assumed: factorize() looks at every entry of A_ce and
/// factorizes the whole matrix when one is not exactly zero (or when there is no
/// extension unknown), so a future term that couples the two still gets a correct solve.
#include <vector>

#include "solve/mumps_lu.hpp"
#include "solve/sparse_lu.hpp"

namespace fsi::solve {

class SplitLU {
 public:
  using Matrix = SparseLU::Matrix;

  /// Factorizes `a` (compressed, square). extension[i] != 0 marks unknown i (row and
  /// column) as an extension unknown. Returns false if a block (or the whole) is singular.
  /// threads >= 2: the two blocks are factorized at the same time, the extension block on
  /// a thread of its own. They are independent LUs, so the factors are the same bits
  /// whatever the thread count.
  bool factorize(const Matrix& a, const std::vector<char>& extension, int threads = 1);
  /// Solves A x = b with the last factorization. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  bool factorized() const { return split_ ? coupled_.factorized() && extension_.factorized() : whole_.factorized(); }
  /// Whether the last factorization used the two blocks (false: the whole matrix).
  bool split() const { return split_; }
  /// Unknowns in the coupled block of the last split factorization.
  Eigen::Index coupled_size() const { return coupled_rows_.size(); }
  /// Symbolic analyses of all three LUs so far.
  int symbolic_analyses() const {
    return whole_.symbolic_analyses() + coupled_.symbolic_analyses() + extension_.symbolic_analyses();
  }

 private:
  /// Rebuilds the blocks' patterns and the positions of their entries in `a`.
  void index_blocks(const Matrix& a, const std::vector<char>& extension);
  /// The blocks' values from `a`; false if an entry of A_ce is not zero.
  bool gather_values(const Matrix& a);

  // The coupled block (and the whole matrix) by MUMPS, the extension block by UMFPACK:
  // each where it is faster (solve/mumps_lu.hpp); MUMPS only ever on the calling thread.
  MumpsLU whole_, coupled_;
  SparseLU extension_;
  bool split_ = false;
  // The partition and pattern the block indexing below was built for.
  std::vector<char> partition_;
  Eigen::VectorXi pattern_outer_, pattern_inner_;
  std::vector<int> coupled_rows_, extension_rows_;  ///< block index -> unknown
  Matrix a_cc_, a_ee_, a_ec_;                       ///< a_ec_: rows extension, columns coupled
  std::vector<int> from_cc_, from_ee_, from_ec_;    ///< entry k of a block <- entry of a
  std::vector<int> ce_entries_;                     ///< entries of a in A_ce
};

}  // namespace fsi::solve
