#include "mesh/patch_colouring.hpp"

#include <algorithm>

namespace fsi::mesh {

std::vector<std::vector<int>> colour_patches(const PatchMesh& mesh) {
  // Patches at each node, then the smallest colour no patch sharing a node already has.
  std::vector<std::vector<int>> patches_at(mesh.num_nodes());
  for (int p = 0; p < mesh.num_patches(); ++p)
    for (int node : mesh.patches[p].node) patches_at[node].push_back(p);
  std::vector<int> colour(mesh.num_patches(), -1);
  std::vector<std::vector<int>> groups;
  std::vector<char> taken;
  for (int p = 0; p < mesh.num_patches(); ++p) {
    taken.assign(groups.size() + 1, 0);
    for (int node : mesh.patches[p].node)
      for (int q : patches_at[node])
        if (colour[q] >= 0) taken[colour[q]] = 1;
    const int c = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    if (c == static_cast<int>(groups.size())) groups.emplace_back();
    colour[p] = c;
    groups[c].push_back(p);
  }
  return groups;
}

}  // namespace fsi::mesh
