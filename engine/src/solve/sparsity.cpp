#include "solve/sparsity.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace fsi::solve {

SparseMatrix build_pattern(const mesh::PatchMesh& mesh, int fields,
                           const FieldCoupling& patch_coupling,
                           const FieldCoupling& neighbor_coupling) {
  const int n = mesh.num_nodes();
  // The four fine quads of every patch, by global node ids.
  std::vector<std::array<int, 4>> quads;
  quads.reserve(4 * mesh.patches.size());
  for (const mesh::Patch& p : mesh.patches)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int l = 3 * j + i;
        quads.push_back({p.node[l], p.node[l + 1], p.node[l + 4], p.node[l + 3]});
      }
  std::vector<std::vector<int>> same(n), near(n);
  std::map<std::pair<int, int>, std::vector<int>> quads_of_edge;
  for (int q = 0; q < static_cast<int>(quads.size()); ++q) {
    for (int a : quads[q])
      for (int b : quads[q]) same[a].push_back(b);
    for (int i = 0; i < 4; ++i) quads_of_edge[std::minmax(quads[q][i], quads[q][(i + 1) % 4])].push_back(q);
  }
  for (const auto& [edge, qs] : quads_of_edge)
    for (int q1 : qs)
      for (int q2 : qs)
        for (int a : quads[q1])
          for (int b : quads[q2]) near[a].push_back(b);
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
