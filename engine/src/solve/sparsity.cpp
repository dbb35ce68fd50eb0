#include "solve/sparsity.hpp"

#include <algorithm>

namespace fsi::solve {

SparseMatrix build_pattern(const mesh::PatchMesh& mesh, int fields,
                           const FieldCoupling& patch_coupling,
                           const FieldCoupling& neighbor_coupling) {
  const int n = mesh.num_nodes();
  // Node-level adjacency, sorted unique per node, for both coupling kinds.
  std::vector<std::vector<int>> same(n), near(n);
  for (const mesh::Patch& p : mesh.patches) {
    for (int a : p.node)
      for (int b : p.node) same[a].push_back(b);
    for (int q : p.neighbor) {
      if (q < 0) continue;
      for (int a : p.node)
        for (int b : mesh.patches[q].node) near[a].push_back(b);
    }
  }
  auto unique = [](std::vector<int>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  std::vector<Eigen::Triplet<double>> triplets;
  for (int a = 0; a < n; ++a) {
    unique(same[a]);
    unique(near[a]);
    for (int fr = 0; fr < fields; ++fr)
      for (int fc = 0; fc < fields; ++fc) {
        if (patch_coupling[fr][fc])
          for (int b : same[a]) triplets.emplace_back(fields * a + fr, fields * b + fc, 0.0);
        if (neighbor_coupling[fr][fc])
          for (int b : near[a]) triplets.emplace_back(fields * a + fr, fields * b + fc, 0.0);
      }
  }
  SparseMatrix m(fields * n, fields * n);
  m.setFromTriplets(triplets.begin(), triplets.end());  // duplicates summed (zeros)
  m.makeCompressed();
  return m;
}

}  // namespace fsi::solve
