#include "mesh/patch_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "mesh/axis.hpp"
#include "mesh/walls.hpp"

namespace fsi::mesh {
namespace {

/// Merges nodes whose coordinates agree to a relative 1e-10 (blocks meet node to node).
class NodeMerger {
 public:
  explicit NodeMerger(double scale) : tol_(1e-10 * scale) {}
  int add(const Vec2& x, std::vector<Vec2>& nodes) {
    const long long ix = std::llround(x.x() / tol_ / 16.0);
    const long long iy = std::llround(x.y() / tol_ / 16.0);
    // Look in the neighbouring buckets too, so rounding at a bucket border cannot split.
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = buckets_.find(key(ix + dx, iy + dy));
        if (it == buckets_.end()) continue;
        for (int id : it->second)
          if ((nodes[id] - x).norm() <= tol_) return id;
      }
    const int id = static_cast<int>(nodes.size());
    nodes.push_back(x);
    buckets_[key(ix, iy)].push_back(id);
    return id;
  }

 private:
  static long long key(long long ix, long long iy) { return ix * 1000003LL + iy; }
  double tol_;
  std::unordered_map<long long, std::vector<int>> buckets_;
};

/// Position of reference point (s, t) in [0,1]^2 of a block.
struct BlockMap {
  const BlockSpec& spec;
  Vec2 operator()(double s, double t) const {
    if (!spec.mapped) return {s, t};  // axes are physical coordinates already
    const auto& c = spec.corners;
    const double x = (1 - s) * (1 - t) * c[0].x + s * (1 - t) * c[1].x + s * t * c[2].x +
                     (1 - s) * t * c[3].x;
    const double y = (1 - s) * (1 - t) * c[0].y + s * (1 - t) * c[1].y + s * t * c[2].y +
                     (1 - s) * t * c[3].y;
    return {x, y};
  }
};

}  // namespace

PatchMesh build_patch_mesh(const MeshSpec& spec, const std::vector<Segment2>& walls) {
  if (spec.blocks.empty()) throw std::invalid_argument("mesh has no blocks");
  PatchMesh mesh;
  double scale = 1.0;
  for (const BlockSpec& b : spec.blocks) {
    for (const auto* axis : {&b.x, &b.y})
      for (const AxisPiece& p : *axis) scale = std::max({scale, std::abs(p.from_m), std::abs(p.to_m)});
    if (b.mapped)
      for (const Point2& c : b.corners) scale = std::max({scale, std::abs(c.x), std::abs(c.y)});
  }
  NodeMerger merger(scale);

  for (const BlockSpec& block : spec.blocks) {
    const std::vector<double> xs = refine_lines(axis_lines(block.x), spec.refinements);
    const std::vector<double> ys = refine_lines(axis_lines(block.y), spec.refinements);
    // Rows along the right side (a fan block): the same count, validated by check_mesh.
    const std::vector<double> ys_right =
        block.y_right.empty() ? ys : refine_lines(axis_lines(block.y_right), spec.refinements);
    const bool fan = !block.y_right.empty();
    if (ys_right.size() != ys.size())
      throw std::invalid_argument("mesh block: y_right has another number of patches than y");
    const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
    const BlockMap map{block};
    // Fine grid of the block: (2 nx + 1) x (2 ny + 1) nodes; midpoints halve the lines.
    auto fine = [](const std::vector<double>& lines, int i) {
      return i % 2 == 0 ? lines[i / 2] : 0.5 * (lines[i / 2] + lines[i / 2 + 1]);
    };
    const int fx = 2 * nx + 1, fy = 2 * ny + 1;
    std::vector<int> id(static_cast<std::size_t>(fx) * fy);
    for (int j = 0; j < fy; ++j)
      for (int i = 0; i < fx; ++i) {
        const int before = mesh.num_nodes();
        // Transfinite between the sides: row j runs straight from its left node to its
        // right node, so midpoints stay midpoints (t is linear in s). Without y_right, t is
        // the left value itself (not a blend that could round it differently).
        const double s = fine(xs, i);
        const double t = fan ? (1.0 - s) * fine(ys, j) + s * fine(ys_right, j) : fine(ys, j);
        id[j * fx + i] = merger.add(map(s, t), mesh.nodes);
        if (mesh.num_nodes() > before) mesh.is_corner.push_back(i % 2 == 0 && j % 2 == 0);
      }
    for (int pj = 0; pj < ny; ++pj)
      for (int pi = 0; pi < nx; ++pi) {
        Patch patch;
        for (int lj = 0; lj < 3; ++lj)
          for (int li = 0; li < 3; ++li)
            patch.node[3 * lj + li] = id[(2 * pj + lj) * fx + 2 * pi + li];
        const auto& n = mesh.nodes;
        const double wx = 0.5 * ((n[patch.node[2]] - n[patch.node[0]]).norm() +
                                 (n[patch.node[8]] - n[patch.node[6]]).norm());
        const double wy = 0.5 * ((n[patch.node[6]] - n[patch.node[0]]).norm() +
                                 (n[patch.node[8]] - n[patch.node[2]]).norm());
        patch.size_m = std::max(wx, wy);
        patch.min_size_m = std::min(wx, wy);
        mesh.patches.push_back(patch);
      }
  }

  // Grid edges and patch neighbours, matched by their corner pair.
  std::map<std::pair<int, int>, std::pair<int, int>> side_of;  // (min,max) -> (patch, side)
  for (int p = 0; p < mesh.num_patches(); ++p) {
    Patch& patch = mesh.patches[p];
    patch.neighbor.fill(-1);
    for (int s = 0; s < 4; ++s) {
      const int a = patch.node[kSideCorners[s][0]], b = patch.node[kSideCorners[s][1]];
      const auto key = std::minmax(a, b);
      auto it = side_of.find(key);
      if (it == side_of.end()) {
        side_of.emplace(key, std::make_pair(p, s));
        patch.edge[s] = static_cast<int>(mesh.edges.size());
        mesh.edges.push_back(GridEdge{a, b, patch.node[kSideMidpoint[s]], -1, true});
      } else {
        const auto [q, t] = it->second;
        if (mesh.patches[q].neighbor[t] != -1)
          throw std::invalid_argument("mesh blocks overlap: a patch side is shared three times");
        patch.neighbor[s] = q;
        mesh.patches[q].neighbor[t] = p;
        patch.edge[s] = mesh.patches[q].edge[t];
        mesh.edges[patch.edge[s]].boundary = false;
        if (mesh.edges[patch.edge[s]].mid != patch.node[kSideMidpoint[s]])
          throw std::invalid_argument("mesh blocks do not meet node to node");
      }
    }
  }

  for (int p = 0; p < mesh.num_patches(); ++p) {
    const Patch& patch = mesh.patches[p];
    for (int s = 0; s < 4; ++s) {
      GridEdge& e = mesh.edges[static_cast<std::size_t>(patch.edge[s])];
      e.patch[e.patch[0] < 0 ? 0 : 1] = p;
      for (int q : {(s + 1) % 4, (s + 3) % 4})
        e.thickness_m = std::min(e.thickness_m, (mesh.nodes[patch.node[kSideCorners[q][1]]] -
                                                 mesh.nodes[patch.node[kSideCorners[q][0]]]).norm());
    }
  }

  mesh.on_wall.assign(mesh.nodes.size(), 0);
  mesh.on_boundary.assign(mesh.nodes.size(), 0);
  for (GridEdge& e : mesh.edges) {
    if (!e.boundary) continue;
    for (int n : {e.a, e.mid, e.b}) mesh.on_boundary[n] = 1;
    const double len = (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (distance_to_segment(walls[w], mesh.nodes[e.a]) < 1e-9 * len &&
          distance_to_segment(walls[w], mesh.nodes[e.b]) < 1e-9 * len) {
        e.wall = static_cast<int>(w);
        for (int n : {e.a, e.mid, e.b}) mesh.on_wall[n] = 1;
        break;
      }
    }
  }
  mesh.min = mesh.max = mesh.nodes.front();
  for (const Vec2& x : mesh.nodes) {
    mesh.min = mesh.min.cwiseMin(x);
    mesh.max = mesh.max.cwiseMax(x);
  }
  return mesh;
}

}  // namespace fsi::mesh
