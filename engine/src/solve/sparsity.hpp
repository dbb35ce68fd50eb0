#pragma once
/// \file sparsity.hpp
/// The fixed sparsity pattern of the monolithic system and fast value accumulation.
///
/// Whatever the interface does, a sub-element never leaves its patch, so all couplings
/// live inside a patch (9 nodes) or, for the CIP pressure stabilization, between the
/// 18 nodes of two patches sharing a side. The pattern is built once per mesh; only
/// values change, so the symbolic LU analysis is reused for the whole run.
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
/// nodes of the same patch; `neighbor_coupling` to nodes of side-adjacent patches.
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
