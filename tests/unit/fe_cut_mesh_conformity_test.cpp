// The cut mesh stays a conforming triangulation/quadrangulation of the domain for a
// curved interface on uniform, graded and mapped meshes: every interior sub-element edge
// is shared by exactly two sub-elements (with opposite orientation), every other edge
// lies on the domain boundary, the areas add up, the interface polyline is closed.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "fe/cut_mesh.hpp"
#include "fe_test_meshes.hpp"

namespace {

using fsi::test::Vec2;

struct Domain {
  std::string name;
  fsi::mesh::PatchMesh mesh;
  std::vector<Vec2> outline;  // the domain polygon (counter-clockwise)
};

std::vector<Domain> domains() {
  using fsi::Point2;
  const std::array<Point2, 4> quad{Point2{-1.0, -1.1}, Point2{1.2, -0.9}, Point2{1.0, 1.0}, Point2{-0.9, 1.2}};
  return {
      {"uniform", fsi::test::block_mesh(16, 16, 2.0, 2.0), {{0, 0}, {2, 0}, {2, 2}, {0, 2}}},
      {"graded", fsi::test::graded_square(8, 1), {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}},
      {"mapped", fsi::test::block_mesh(12, 10, 1.0, 1.0, true, quad),
       {{-1.0, -1.1}, {1.2, -0.9}, {1.0, 1.0}, {-0.9, 1.2}}},
  };
}

TEST(CutMeshConformity, EverySubElementEdgeIsSharedOrOnTheBoundary) {
  for (const Domain& d : domains()) {
    SCOPED_TRACE(d.name);
    Vec2 centre = Vec2::Zero();
    for (const Vec2& v : d.outline) centre += 0.25 * v;
    centre += Vec2(0.0123, -0.0311);
    const double r = 0.55;
    const auto phi = [&](const Vec2& x) { return (x - centre).norm() - r; };
    const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(d.mesh, phi);
    int cut_patches = 0;
    for (auto k : cut.kind) cut_patches += k != fsi::fe::PatchKind::uncut;
    EXPECT_GT(cut_patches, 8);

    // Directed edges: an interior edge appears once in each direction.
    std::map<std::pair<int, int>, int> directed;
    double area = 0.0;
    for (const auto& e : cut.elements) {
      area += fsi::fe::element_area(cut, e);
      for (int i = 0; i < e.vertices; ++i) ++directed[{e.node[i], e.node[(i + 1) % e.vertices]}];
    }
    EXPECT_NEAR(area, fsi::test::polygon_area(d.outline), 1e-13);
    int boundary_edges = 0;
    for (const auto& [edge, count] : directed) {
      ASSERT_EQ(count, 1) << "edge used twice in the same direction (overlap or inversion)";
      if (directed.count({edge.second, edge.first})) continue;
      ++boundary_edges;
      EXPECT_TRUE(d.mesh.on_boundary[edge.first] && d.mesh.on_boundary[edge.second])
          << "hanging sub-element edge " << edge.first << "-" << edge.second;
    }
    int boundary_grid_edges = 0;
    for (const auto& g : d.mesh.edges) boundary_grid_edges += g.boundary;
    EXPECT_EQ(boundary_edges, 2 * boundary_grid_edges);

    // Closed interface through nodes on the circle (moved edge nodes are on it exactly).
    std::map<int, int> count;
    for (const auto& s : cut.interface) {
      ++count[s.node[0]];
      ++count[s.node[1]];
    }
    for (const auto& [node, n] : count) EXPECT_EQ(n, 2) << "open interface at node " << node;
    EXPECT_EQ(cut.saddle_patches, 0);
  }
}

TEST(CutMeshConformity, NeighbouringPatchesSeeTheSameMovedEdgeNode) {
  // The cut point is computed once per grid edge: both patches use the same node, whose
  // position is on the level set and on the grid edge.
  const auto mesh = fsi::test::block_mesh(10, 10, 1.0, 1.0);
  const Vec2 c(0.43, 0.51);
  const auto phi = [&](const Vec2& x) { return (x - c).norm() - 0.31; };
  const fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi);
  int moved = 0;
  for (const auto& g : mesh.edges) {
    if ((cut.x[g.mid] - mesh.nodes[g.mid]).norm() == 0.0) continue;
    ++moved;
    EXPECT_NEAR(phi(cut.x[g.mid]), 0.0, 1e-13);
    const Vec2 ab = mesh.nodes[g.b] - mesh.nodes[g.a], am = cut.x[g.mid] - mesh.nodes[g.a];
    EXPECT_NEAR(ab.x() * am.y() - ab.y() * am.x(), 0.0, 1e-15);
  }
  EXPECT_GT(moved, 10);
}

}  // namespace
