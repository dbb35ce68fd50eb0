#pragma once
/// \file sparsity.hpp
/// The fixed sparsity pattern of the monolithic system and fast value accumulation.
///
/// Whatever the interface does, every sub-element (sub-quad or sub-triangle of any cut
/// configuration A-D) has its nodes inside one *fine quad* -- one quarter of a patch,
/// a 2x2 block of the 3x3 patch nodes. So element couplings never leave a fine quad
/// (a 9-point stencil on the node grid), and the CIP edge terms, which couple the
/// nodes of two sub-elements sharing an edge, never leave two edge-adjacent fine quads.
/// The pattern is built once per mesh; only values change, so the symbolic LU analysis
/// is reused for the whole run. (Coupling all 9 patch nodes instead gives 72 instead of
/// 40 entries per row and a 3x slower factorization.)
#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/SparseCore>

#include "mesh/patch_mesh.hpp"

namespace fsi::solve {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Which field (column) each field (row) couples to: coupling[row_field][col_field].
using FieldCoupling = std::vector<std::vector<char>>;

/// Pattern with `fields` unknowns per node (node-major). `patch_coupling` applies to
/// nodes of the same fine quad; `neighbor_coupling` to nodes of two edge-adjacent
/// fine quads.
SparseMatrix build_pattern(const mesh::PatchMesh& mesh, int fields,
                           const FieldCoupling& patch_coupling,
                           const FieldCoupling& neighbor_coupling);

/// Index into a compressed column-major matrix's value array of entry (row, col);
/// -1 if the entry is not in the pattern.
inline int value_index(const SparseMatrix& a, int row, int col) {
  const int* begin = a.innerIndexPtr() + a.outerIndexPtr()[col];
  const int* end = a.innerIndexPtr() + a.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? static_cast<int>(it - a.innerIndexPtr()) : -1;
}

}  // namespace fsi::solve
