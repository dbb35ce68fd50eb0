// Every cut configuration of a locally modified patch (A-D, vertex and edge-tangent
// cases, snapped cuts) on a unit square, a bilinearly mapped non-rectangular patch and
// an anisotropic 0.025 x 0.0031 patch, in all four orientations: the sub-elements
// partition the patch exactly, the interface polyline lies on the (linear) level set,
// each sub-element lies on one side and carries that side's phase, the maximum angle
// stays bounded away from 180 degrees.
//
// The angle bound depends on the patch's aspect ratio a = h_long / h_short: the centre
// node must lie on the interface, and when it sits on a long side's far end the fan
// triangle at the opposite long side's midpoint has an angle of 180 deg - atan(1/a)
// (unavoidable with the 3x3 node layout: any triangle joining that midpoint to two
// nodes of the other long side is at least as flat). Frei & Richter's bound assumes
// shape-regular patches (a ~ 1): there we require < 0.95 pi (171 deg).
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "fe/cut_mesh.hpp"
#include "fe_test_meshes.hpp"

namespace {

using fsi::fe::CutMesh;
using fsi::fe::PatchKind;
using fsi::test::Vec2;

struct Geometry {
  const char* name;
  fsi::mesh::PatchMesh mesh;
};

/// A point on the patch boundary: side s (0 bottom, 1 right, 2 top, 3 left, i.e. from
/// corner s to corner s+1 counter-clockwise) at parameter t.
struct BoundaryPoint {
  int side;
  double t;
};

struct Config {
  const char* name;
  PatchKind kind;
  BoundaryPoint p, q;  // the interface is the line p -> q
  double snapped = 0.0;  // distance (in side lengths) the snapping moves the interface
};

std::vector<Geometry> geometries() {
  using fsi::Point2;
  return {
      {"square", fsi::test::block_mesh(1, 1, 1.0, 1.0)},
      {"mapped", fsi::test::block_mesh(1, 1, 1.0, 1.0, true,
                                       {Point2{0.0, 0.0}, Point2{1.1, 0.2}, Point2{1.3, 1.0}, Point2{-0.2, 0.8}})},
      {"anisotropic", fsi::test::block_mesh(1, 1, 0.025, 0.0031)},
  };
}

// Positions relative to a starting corner k (the rotation): side j means side k + j.
const std::vector<Config> kConfigs{
    {"A", PatchKind::A, {3, 0.7}, {0, 0.4}},
    {"A_large", PatchKind::A, {3, 0.1}, {0, 0.9}},
    {"A_tiny", PatchKind::A, {3, 1.0 - 1e-5}, {0, 1e-5}},
    {"B", PatchKind::B, {0, 0.3}, {2, 0.6}},
    {"B_near_side", PatchKind::B, {0, 1e-5}, {2, 1.0 - 1e-5}},
    {"C", PatchKind::C, {0, 0.0}, {1, 0.4}},
    {"C_top", PatchKind::C, {0, 0.0}, {2, 0.3}},
    {"C_near_corner", PatchKind::C, {0, 0.0}, {1, 1e-5}},
    {"C_from_snapped_cut", PatchKind::C, {0, 1e-10}, {2, 0.5}, 1e-10},
    {"D", PatchKind::D, {0, 0.0}, {2, 0.0}},
    {"edge_tangent", PatchKind::uncut, {0, 0.0}, {1, 0.0}},
    {"snapped_to_vertex", PatchKind::uncut, {3, 1.0 - 1e-9}, {0, 1e-9}, 1e-9},
};

class CutConfiguration : public ::testing::TestWithParam<Config> {};

Vec2 corner(const fsi::mesh::PatchMesh& m, int k) {
  return m.nodes[m.patches[0].node[fsi::mesh::kCornerLocal[(k % 4 + 4) % 4]]];
}
Vec2 boundary_point(const fsi::mesh::PatchMesh& m, int k, BoundaryPoint b) {
  const Vec2 a = corner(m, k + b.side), c = corner(m, k + b.side + 1);
  return a + b.t * (c - a);
}

void check_cut(const fsi::mesh::PatchMesh& mesh, const CutMesh& cut, const fsi::test::LineLevelSet& phi,
               PatchKind kind, double snapped) {
  EXPECT_EQ(cut.kind[0], kind);
  ASSERT_EQ(cut.elements.size(), kind == PatchKind::uncut ? 4u : 8u);
  std::vector<Vec2> corners;
  for (int k = 0; k < 4; ++k) corners.push_back(corner(mesh, k));
  const double area = fsi::test::polygon_area(corners);
  const double size = (corners[2] - corners[0]).norm();
  const double w = 0.5 * ((corners[1] - corners[0]).norm() + (corners[2] - corners[3]).norm());
  const double h = 0.5 * ((corners[3] - corners[0]).norm() + (corners[2] - corners[1]).norm());
  const double aspect = std::max(w, h) / std::min(w, h);
  const double tol = (1e-13 + 2.0 * snapped) * size;  // snapping moves the interface
  const double max_angle = aspect < 2.0 ? 0.95 * std::numbers::pi
                                        : std::numbers::pi - 0.5 * std::atan(1.0 / aspect);
  double sum = 0.0;
  for (const auto& e : cut.elements) {
    const double a = fsi::fe::element_area(cut, e);
    EXPECT_GT(a, 0.0) << "inverted or degenerate sub-element";
    sum += a;
    EXPECT_LT(fsi::fe::element_angle_range(cut, e)[1], max_angle);
    if (kind == PatchKind::uncut) continue;
    // One side of the interface, and the phase of that side.
    double lo = 1e300, hi = -1e300;
    Vec2 centroid = Vec2::Zero();
    for (int i = 0; i < e.vertices; ++i) {
      lo = std::min(lo, phi(cut.x[e.node[i]]));
      hi = std::max(hi, phi(cut.x[e.node[i]]));
      centroid += cut.x[e.node[i]] / e.vertices;
    }
    EXPECT_TRUE(lo >= -tol || hi <= tol) << "sub-element straddles the interface";
    EXPECT_EQ(e.phase == fsi::Phase::solid, phi(centroid) < 0.0);
  }
  EXPECT_NEAR(sum, area, 1e-14 * area);
  for (const auto& s : cut.interface) {
    EXPECT_NEAR(phi(s.a), 0.0, tol);
    EXPECT_NEAR(phi(s.b), 0.0, tol);
  }
  EXPECT_EQ(cut.interface.empty(), kind == PatchKind::uncut);
}

TEST_P(CutConfiguration, PartitionsThePatchOnEveryGeometryAndRotation) {
  const Config c = GetParam();
  for (const Geometry& g : geometries())
    for (int k = 0; k < 4; ++k)
      for (bool flip : {false, true}) {  // both colourings
        SCOPED_TRACE(std::string(g.name) + " rotation " + std::to_string(k) + (flip ? " flipped" : ""));
        Vec2 p = boundary_point(g.mesh, k, c.p), q = boundary_point(g.mesh, k, c.q);
        if (flip) std::swap(p, q);
        const fsi::test::LineLevelSet phi{p, q};
        check_cut(g.mesh, fsi::fe::build_cut_mesh(g.mesh, phi), phi, c.kind, c.snapped);
      }
}

INSTANTIATE_TEST_SUITE_P(AllConfigurations, CutConfiguration, ::testing::ValuesIn(kConfigs),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(CutConfiguration, VertexTouchLeavesThePatchUncutWithThePhaseOfTheOtherCorners) {
  for (const Geometry& g : geometries())
    for (int k = 0; k < 4; ++k) {
      SCOPED_TRACE(std::string(g.name) + " corner " + std::to_string(k));
      // Line through corner k parallel to the diagonal (k+1, k+3): all other corners on one side.
      const Vec2 p = corner(g.mesh, k);
      const fsi::test::LineLevelSet phi{p, p + corner(g.mesh, k + 1) - corner(g.mesh, k + 3)};
      const CutMesh cut = fsi::fe::build_cut_mesh(g.mesh, phi);
      EXPECT_EQ(cut.kind[0], PatchKind::uncut);
      const bool solid = phi(corner(g.mesh, k + 2)) < 0.0;
      for (const auto& e : cut.elements) EXPECT_EQ(e.phase == fsi::Phase::solid, solid);
    }
}

}  // namespace
