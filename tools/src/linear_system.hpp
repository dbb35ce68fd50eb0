#pragma once
/// \file linear_system.hpp
/// Small helpers of the studies around a matrix with the fixed sparsity pattern
/// (solve/sparsity.hpp): scatter of element matrices and Dirichlet constraints.
#include <vector>

#include <Eigen/Core>

#include "solve/sparsity.hpp"

namespace fsi::study {

/// a(row, col) += v; the entry must be in the pattern (a study bug otherwise: throws).
void add_entry(solve::SparseMatrix& a, int row, int col, double v);

/// Imposes x[i] = value[i] for every i with fixed[i]: the row becomes d_i * x_i = d_i *
/// value_i with d_i the former diagonal (keeps the matrix scaled like the operator, so
/// UMFPACK's rcond measures the discretisation, not our constraint scaling), and the
/// column is eliminated into the right-hand side (keeps a symmetric operator symmetric).
void apply_dirichlet(solve::SparseMatrix& a, Eigen::VectorXd& rhs, const std::vector<char>& fixed,
                     const Eigen::VectorXd& value);

}  // namespace fsi::study
