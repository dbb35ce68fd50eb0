#include "core/contact_release.hpp"

#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include "fsi/state.hpp"

namespace fsi::core {

namespace {

/// Union-find over the (node, wall) contact points.
int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<char> released_wall_nodes(const mesh::PatchMesh& mesh, const std::vector<char>& touches_solid,
                                      const std::vector<char>& touched_solid, const Eigen::VectorXd& wall_force) {
  const std::size_t nodes = mesh.nodes.size();
  if (touches_solid.size() != nodes || touched_solid.size() != nodes ||
      wall_force.size() != kFieldsPerNode * static_cast<Eigen::Index>(nodes))
    return {};
  // Contact points: a wall node touching the solid, once per wall it lies on, with the
  // wall's push on it along that wall's inward direction (local 3 x 3 numbering: the node
  // one row inside from a node of side s).
  constexpr int kInward[4] = {3, -1, -3, 1};
  std::map<std::pair<int, int>, int> point;  // (node, wall) -> index
  std::vector<std::pair<int, int>> where;
  std::vector<double> push;
  for (const mesh::Patch& patch : mesh.patches) {
    for (int s = 0; s < 4; ++s) {
      const int e = patch.edge[s];
      if (e < 0 || mesh.edges[e].wall < 0) continue;
      for (int l : {mesh::kSideCorners[s][0], mesh::kSideMidpoint[s], mesh::kSideCorners[s][1]}) {
        const int w = patch.node[l];
        if (!touches_solid[w]) continue;
        const auto [it, inserted] = point.emplace(std::make_pair(w, mesh.edges[e].wall), static_cast<int>(push.size()));
        if (!inserted) continue;
        const Eigen::Vector2d inward = (mesh.nodes[patch.node[l + kInward[s]]] - mesh.nodes[w]).normalized();
        where.push_back(it->first);
        // A node the solid reaches this step holds its patch: its row at the step's start
        // was not the solid's, and the patch grows, pressed on.
        push.push_back(!touched_solid[w] ? std::numeric_limits<double>::infinity()
                                         : inward.x() * wall_force[kFieldsPerNode * w + kVx] +
                                               inward.y() * wall_force[kFieldsPerNode * w + kVy]);
      }
    }
  }
  if (push.empty()) return {};
  // Contact patches: the points joined by wall edges of one wall, both ends touching.
  std::vector<int> parent(push.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const mesh::GridEdge& e : mesh.edges) {
    if (e.wall < 0) continue;
    int previous = -1;
    for (int n : {e.a, e.mid, e.b}) {
      const auto it = n < 0 ? point.end() : point.find({n, e.wall});
      const int current = it == point.end() ? -1 : it->second;
      if (previous >= 0 && current >= 0) parent[find_root(parent, previous)] = find_root(parent, current);
      previous = current;
    }
  }
  std::vector<double> patch_push(push.size(), 0.0);
  for (std::size_t i = 0; i < push.size(); ++i) patch_push[find_root(parent, static_cast<int>(i))] += push[i];
  // 1: every contact patch through the node pulls so far; 2: one of them pushes.
  std::vector<char> state(nodes, 0);
  for (std::size_t i = 0; i < push.size(); ++i) {
    const int n = where[i].first;
    if (!(patch_push[find_root(parent, static_cast<int>(i))] < 0.0)) state[n] = 2;
    else if (state[n] == 0) state[n] = 1;
  }
  std::vector<char> released(nodes, 0);
  bool any = false;
  for (std::size_t n = 0; n < nodes; ++n) {
    released[n] = state[n] == 1;
    any = any || released[n];
  }
  if (!any) released.clear();
  return released;
}

std::vector<char> turned_round(const mesh::PatchMesh& mesh, const std::vector<char>& touches_solid,
                               const std::vector<char>& released) {
  const std::size_t nodes = mesh.nodes.size();
  std::vector<char> turned(nodes, 0);
  bool any = false;
  for (std::size_t n = 0; n < nodes; ++n) {
    turned[n] = mesh.on_wall[n] && touches_solid[n] && !(!released.empty() && released[n]);
    any = any || turned[n];
  }
  if (!any) turned.clear();
  return turned;
}

}  // namespace fsi::core
