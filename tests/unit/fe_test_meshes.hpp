#pragma once
// Small meshes and level sets shared by the FE core tests.
#include <array>
#include <cmath>
#include <vector>

#include "fsi/scenario.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::test {

using mesh::Vec2;

/// One block of nx x ny patches; uniform axes on [x0, x0 + w] x [y0, y0 + h], or mapped
/// onto the quadrilateral `corners` (counter-clockwise) when `mapped`; `walls` marked.
inline mesh::PatchMesh block_mesh(int nx, int ny, double w, double h, bool mapped = false,
                                  std::array<Point2, 4> corners = {}, int refinements = 0,
                                  const std::vector<Segment2>& walls = {}) {
  BlockSpec b;
  b.x = {AxisPiece{0.0, mapped ? 1.0 : w, nx, 0.0, 0.0}};
  b.y = {AxisPiece{0.0, mapped ? 1.0 : h, ny, 0.0, 0.0}};
  b.mapped = mapped;
  b.corners = corners;
  MeshSpec spec;
  spec.blocks = {b};
  spec.refinements = refinements;
  return mesh::build_patch_mesh(spec, walls);
}

/// (-1,1)^2 graded 1:4 in x (growing) and 4:1 in y (shrinking), as in the studies.
inline mesh::PatchMesh graded_square(int patches, int refinements = 0) {
  BlockSpec b;
  const double first = 2.0 / (2.5 * patches);  // linear growth h0 .. 4 h0 fills 2
  b.x = {AxisPiece{-1.0, 1.0, patches, first, 4 * first}};
  b.y = {AxisPiece{-1.0, 1.0, patches, 4 * first, first}};
  MeshSpec spec;
  spec.blocks = {b};
  spec.refinements = refinements;
  return mesh::build_patch_mesh(spec, {});
}

/// Signed distance to the line through p and q (positive on the left of p -> q).
struct LineLevelSet {
  Vec2 p, q;
  double operator()(const Vec2& x) const {
    const Vec2 d = (q - p).normalized();
    return d.x() * (x - p).y() - d.y() * (x - p).x();
  }
};

/// Signed area of a polygon (shoelace).
inline double polygon_area(const std::vector<Vec2>& v) {
  double a = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& p = v[i];
    const Vec2& q = v[(i + 1) % v.size()];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

}  // namespace fsi::test
