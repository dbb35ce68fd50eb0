#include "core/contact_release.hpp"

#include <cmath>

namespace fsi::core {

std::vector<char> released_wall_nodes(const mesh::PatchMesh& mesh, const std::vector<Segment2>& walls,
                                      const std::vector<char>& touches_solid,
                                      const Eigen::Vector2d& body_velocity_mps, const Eigen::Vector2d& centroid_m) {
  const std::size_t nodes = mesh.nodes.size();
  if (touches_solid.size() != nodes) return {};
  // Per wall: does the body move away from it (normal towards the centroid)?
  std::vector<char> leaving(walls.size(), 0);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Eigen::Vector2d a(walls[w].a.x, walls[w].a.y), b(walls[w].b.x, walls[w].b.y);
    Eigen::Vector2d n(-(b - a).y(), (b - a).x());
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    if ((centroid_m - a).dot(n) < 0.0) n = -n;
    leaving[w] = body_velocity_mps.dot(n) > kReleaseSpeed_mps;
  }
  // 1: on a wall it leaves so far; 2: also on a wall it does not leave (held).
  std::vector<char> state(nodes, 0);
  bool any = false;
  for (const mesh::GridEdge& e : mesh.edges) {
    if (e.wall < 0 || e.wall >= static_cast<int>(walls.size())) continue;
    for (int n : {e.a, e.mid, e.b}) {
      if (n < 0 || !touches_solid[n]) continue;
      if (!leaving[e.wall]) state[n] = 2;
      else if (state[n] == 0) state[n] = 1;
    }
  }
  std::vector<char> released(nodes, 0);
  for (std::size_t n = 0; n < nodes; ++n) {
    released[n] = state[n] == 1;
    any = any || released[n];
  }
  if (!any) released.clear();
  return released;
}

}  // namespace fsi::core
