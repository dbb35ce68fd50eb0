#include "linear_system.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::study {

void add_entry(solve::SparseMatrix& a, int row, int col, double v) {
  const int k = solve::value_index(a, row, col);
  if (k < 0) throw std::logic_error("entry outside the sparsity pattern");
  a.valuePtr()[k] += v;
}

void apply_dirichlet(solve::SparseMatrix& a, Eigen::VectorXd& rhs, const std::vector<char>& fixed,
                     const Eigen::VectorXd& value) {
  const int n = static_cast<int>(a.rows());
  std::vector<double> diag(n, 1.0);
  for (int i = 0; i < n; ++i) {
    const int k = solve::value_index(a, i, i);
    if (fixed[i] && k >= 0 && std::abs(a.valuePtr()[k]) > 0.0) diag[i] = std::abs(a.valuePtr()[k]);
  }
  for (int col = 0; col < n; ++col)
    for (int k = a.outerIndexPtr()[col]; k < a.outerIndexPtr()[col + 1]; ++k) {
      const int row = a.innerIndexPtr()[k];
      if (!fixed[row] && !fixed[col]) continue;
      if (!fixed[row]) rhs[row] -= a.valuePtr()[k] * value[col];
      a.valuePtr()[k] = row == col ? diag[row] : 0.0;
    }
  for (int i = 0; i < n; ++i)
    if (fixed[i]) rhs[i] = diag[i] * value[i];
}

}  // namespace fsi::study
