#include "core/flat_wall_rows.hpp"

#include <algorithm>
#include <cstdio>

namespace fsi::core {
namespace {

/// Whether p lies in the quadrilateral of the patch's corner nodes (reference mesh).
bool patch_holds(const mesh::PatchMesh& mesh, const mesh::Patch& patch, const mesh::Vec2& p) {
  bool positive = false, negative = false;
  for (int s = 0; s < 4; ++s) {
    const mesh::Vec2& a = mesh.nodes[patch.node[mesh::kSideCorners[s][0]]];
    const mesh::Vec2& b = mesh.nodes[patch.node[mesh::kSideCorners[s][1]]];
    const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
    positive |= cross > 0.0;
    negative |= cross < 0.0;
  }
  return !(positive && negative);
}

}  // namespace

WallRow widest_wall_row_near(const mesh::PatchMesh& mesh, Point2 where_m) {
  const mesh::Vec2 p(where_m.x, where_m.y);
  WallRow widest;
  for (const mesh::Patch& holder : mesh.patches) {
    if (!patch_holds(mesh, holder, p)) continue;
    // The holder and its neighbours: a break in the second row still shows the first.
    std::vector<const mesh::Patch*> near{&holder};
    for (int n : holder.neighbor)
      if (n >= 0) near.push_back(&mesh.patches[static_cast<std::size_t>(n)]);
    for (const mesh::Patch* patch : near)
      for (int s = 0; s < 4; ++s) {
        const mesh::GridEdge& e = mesh.edges[static_cast<std::size_t>(patch->edge[s])];
        if (e.wall < 0) continue;
        const double width = (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
        const double thickness = std::min(e.thickness_m, patch->size_m);
        if (thickness <= 0.0 || width / thickness <= widest.aspect) continue;
        widest = {width / thickness, width, thickness, e.wall};
      }
    break;
  }
  return widest;
}

std::string flat_wall_row_note(const mesh::PatchMesh& mesh, Point2 where_m) {
  const WallRow row = widest_wall_row_near(mesh, where_m);
  if (row.aspect <= kFlatWallRowAspect * (1.0 + 1e-9)) return {};  // the limit itself, up to rounding
  char text[512];
  std::snprintf(text, sizeof text,
                "; there wall %d's row of patches is %.0f times as wide as thick (%.3g m along the wall, %.3g m "
                "across), which resolves a flattened body along the wall by few nodes: several landings that broke on "
                "such rows held on rows at most %.0f times as wide as thick (docs/solver.md, \"Flat rows at a wall\")",
                row.wall, row.aspect, row.width_m, row.thickness_m, kFlatWallRowAspect);
  return text;
}

}  // namespace fsi::core
