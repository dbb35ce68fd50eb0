// Every cut configuration of the locally modified FE patch: sub-elements partition the
// patch exactly, the interface polyline lies on the level set, angles stay bounded.
#include "fe/cut_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "fe_test_meshes.hpp"
#include "mesh/patch_mesh.hpp"

namespace {

using fsi::fe::CutMesh;
using fsi::fe::PatchKind;
using fsi::mesh::Vec2;

fsi::mesh::PatchMesh unit_mesh(int patches) { return fsi::test::block_mesh(patches, patches, 1.0, 1.0); }

double total_area(const CutMesh& cut) {
  double a = 0.0;
  for (const auto& e : cut.elements) {
    const double ea = fsi::fe::element_area(cut, e);
    EXPECT_GT(ea, 0.0) << "inverted or degenerate sub-element";
    a += ea;
  }
  return a;
}

struct Case {
  const char* name;
  PatchKind kind;
  double nx, ny, c;  // level set phi = nx x + ny y - c (linear: the interface is exact)
};

class SinglePatchCut : public ::testing::TestWithParam<Case> {};

TEST_P(SinglePatchCut, PartitionsThePatchAndFollowsTheLevelSet) {
  const Case c = GetParam();
  const auto mesh = unit_mesh(1);
  // All four rotations about the patch centre.
  for (int r = 0; r < 4; ++r) {
    const double ang = r * std::numbers::pi / 2;
    auto phi = [&](const Vec2& x) {
      const Vec2 d = x - Vec2(0.5, 0.5);
      const Vec2 y(std::cos(ang) * d.x() + std::sin(ang) * d.y() + 0.5,
                   -std::sin(ang) * d.x() + std::cos(ang) * d.y() + 0.5);
      return c.nx * y.x() + c.ny * y.y() - c.c;
    };
    const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi);
    SCOPED_TRACE(std::string(c.name) + " rotation " + std::to_string(r));
    EXPECT_EQ(cut.kind[0], c.kind);
    EXPECT_NEAR(total_area(cut), 1.0, 1e-14);
    EXPECT_EQ(cut.elements.size(), c.kind == PatchKind::uncut ? 4u : 8u);
    for (const auto& s : cut.interface) {
      EXPECT_NEAR(phi(s.a), 0.0, 1e-13);
      EXPECT_NEAR(phi(s.b), 0.0, 1e-13);
    }
    if (c.kind != PatchKind::uncut) {
      EXPECT_FALSE(cut.interface.empty());
      for (const auto& e : cut.elements) {
        // Maximum angle bounded away from pi (Frei & Richter's condition).
        EXPECT_LT(fsi::fe::element_angle_range(cut, e)[1], std::numbers::pi * 0.95);
        // Each sub-element lies on one side of the (linear) interface.
        double lo = 1e300, hi = -1e300;
        for (int i = 0; i < e.vertices; ++i) {
          lo = std::min(lo, phi(cut.x[e.node[i]]));
          hi = std::max(hi, phi(cut.x[e.node[i]]));
        }
        EXPECT_TRUE(lo >= -1e-13 || hi <= 1e-13);
        EXPECT_EQ(e.phase == fsi::Phase::solid, lo < -1e-13);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, SinglePatchCut,
    ::testing::Values(Case{"A", PatchKind::A, 1.0, 1.0, 0.3}, Case{"A_large", PatchKind::A, 1.0, 1.0, 1.7},
                      Case{"A_tiny", PatchKind::A, 1.0, 1.0, 1e-4},
                      Case{"B", PatchKind::B, 1.0, 0.1, 0.37}, Case{"B_near_edge", PatchKind::B, 1.0, 0.0, 1e-5},
                      Case{"C", PatchKind::C, 0.4, -1.0, 0.0}, Case{"C_top", PatchKind::C, 1.0, -0.3, 0.0},
                      Case{"D", PatchKind::D, 1.0, -1.0, 0.0},
                      Case{"vertex_touch", PatchKind::uncut, 1.0, 1.0, 0.0},
                      Case{"edge_tangent", PatchKind::uncut, 0.0, 1.0, 0.0},
                      Case{"snapped_to_vertex", PatchKind::uncut, 1.0, 1.0, 1e-9}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CutMesh, CircleOnAFinerMeshKeepsAreaAndConformity) {
  const auto mesh = unit_mesh(16);
  const Vec2 centre(0.5123, 0.4871);
  const double r = 0.3;
  auto phi = [&](const Vec2& x) { return (x - centre).norm() - r; };
  const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi);
  EXPECT_NEAR(total_area(cut), 1.0, 1e-13);
  double solid = 0.0;
  for (const auto& e : cut.elements)
    if (e.phase == fsi::Phase::solid) solid += fsi::fe::element_area(cut, e);
  // Polygonal approximation of the disc: O(h^2) area error with h = 1/16.
  EXPECT_NEAR(solid, std::numbers::pi * r * r, 2e-3);
  for (const auto& s : cut.interface) {
    // Chord midpoints (moved centres) lie inside by the sagitta ~ (h sqrt 2)^2 / (8 r).
    EXPECT_NEAR(phi(s.a), 0.0, 2.0 / (16.0 * 16.0) / (8 * r));
  }
  // Interface is closed: every interface node appears in exactly two segments.
  std::map<int, int> count;
  for (const auto& s : cut.interface) {
    ++count[s.node[0]];
    ++count[s.node[1]];
  }
  for (const auto& [node, n] : count) EXPECT_EQ(n, 2) << "open interface at node " << node;
}

// Every interface node in exactly two segments: the polyline has no hole.
void expect_closed(const CutMesh& cut) {
  std::map<int, int> count;
  for (const auto& s : cut.interface) {
    ++count[s.node[0]];
    ++count[s.node[1]];
  }
  EXPECT_FALSE(count.empty());
  for (const auto& [node, n] : count) EXPECT_EQ(n, 2) << "open interface at node " << node;
}

double interface_length(const CutMesh& cut) {
  double length = 0.0;
  for (const auto& s : cut.interface) length += (s.b - s.a).norm();
  return length;
}

TEST(CutMesh, AnInterfaceAlongPatchSidesIsInterfaceToo) {
  // The square [0.25, 0.75]^2 on 4 x 4 patches of 0.25 m: the level set vanishes on whole
  // patch sides, so no patch is cut; the sides between the solid and the fluid patches
  // are the interface (its length 2 m, closed), not a hole in it.
  const auto mesh = unit_mesh(4);
  auto phi = [](const Vec2& x) { return std::max(std::abs(x.x() - 0.5), std::abs(x.y() - 0.5)) - 0.25; };
  const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi);
  for (PatchKind k : cut.kind) EXPECT_EQ(k, PatchKind::uncut);
  EXPECT_NEAR(interface_length(cut), 2.0, 1e-12);
  expect_closed(cut);
  for (const auto& s : cut.interface) {
    EXPECT_NEAR(phi(s.a), 0.0, 1e-12);
    EXPECT_NEAR(phi(s.b), 0.0, 1e-12);
    // Added from the solid side: its patch lies inside the square.
    const Vec2 centre = mesh.nodes[mesh.patches[s.patch].node[4]];
    EXPECT_LT(phi(centre), 0.0);
  }
}

TEST(CutMesh, SnappingCutsToCornersKeepsTheInterfaceClosed) {
  // A generous snap moves many cuts of a circle to corners; where both corners of a side
  // are snapped the side carries the interface, so the polyline stays closed.
  const auto mesh = unit_mesh(16);
  const Vec2 centre(0.5123, 0.4871);
  auto phi = [&](const Vec2& x) { return (x - centre).norm() - 0.3; };
  for (double snap : {3e-2, 0.2, 0.45}) {
    SCOPED_TRACE("snap " + std::to_string(snap));
    const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{snap});
    EXPECT_NEAR(total_area(cut), 1.0, 1e-13);
    EXPECT_NEAR(interface_length(cut), 2 * std::numbers::pi * 0.3, 0.1);
    expect_closed(cut);
  }
}

TEST(CutMesh, ASnapDistanceTreatsShortAndLongSidesAlike) {
  // Flat patches like the stairs' thin rows: 5.6 cm wide, 8 mm tall. A relative snap large
  // enough for a cut 0.6 mm from a corner on a short side (7.5 %) would move cuts on the
  // long sides by up to 4 mm; a snap distance of 0.8 mm takes the first and leaves a cut
  // 1.9 mm from a corner on a long side alone.
  const auto mesh = fsi::test::block_mesh(2, 2, 0.112, 0.016);
  auto sign_at = [&](const fsi::fe::CutData& data, double x, double y) {
    for (int n = 0; n < mesh.num_nodes(); ++n)
      if ((mesh.nodes[n] - Vec2(x, y)).norm() < 1e-12) return static_cast<int>(data.corner_sign[n]);
    ADD_FAILURE() << "no corner at (" << x << ", " << y << ")";
    return 99;
  };
  auto cut_edges = [](const fsi::fe::CutData& data) {
    return std::count_if(data.edge_cut.begin(), data.edge_cut.end(), [](double t) { return t >= 0.0; });
  };
  const fsi::fe::CutOptions relative{3e-2, 0.0}, distance{3e-2, 8e-4};

  // Short sides cut 0.6 mm above the row y = 8 mm.
  auto low = [](const Vec2& x) { return x.y() - 0.0086; };
  const auto short_relative = fsi::fe::cut_data(mesh, low, relative);
  EXPECT_EQ(sign_at(short_relative, 0.056, 0.008), -1);
  EXPECT_EQ(cut_edges(short_relative), 3);
  const auto short_distance = fsi::fe::cut_data(mesh, low, distance);
  for (double x : {0.0, 0.056, 0.112}) EXPECT_EQ(sign_at(short_distance, x, 0.008), 0) << x;
  EXPECT_EQ(cut_edges(short_distance), 0);

  // Long sides cut 1.9 mm right of the column x = 5.6 cm (3.4 % of the side).
  auto right = [](const Vec2& x) { return x.x() - 0.0579; };
  const auto long_relative = fsi::fe::cut_data(mesh, right, fsi::fe::CutOptions{5e-2, 0.0});
  EXPECT_EQ(sign_at(long_relative, 0.056, 0.0), 0);
  const auto long_distance = fsi::fe::cut_data(mesh, right, distance);
  EXPECT_EQ(sign_at(long_distance, 0.056, 0.0), -1);
  EXPECT_EQ(cut_edges(long_distance), 3);

  // Either way the sub-elements still tile the patches.
  for (const auto* data : {&short_distance, &long_distance}) {
    const CutMesh cut = fsi::fe::build_cut_mesh(mesh, *data);
    EXPECT_NEAR(total_area(cut), 0.112 * 0.016, 1e-15);
  }
}

TEST(CutMesh, ASnapDistanceLongerThanHalfASideSnapsToTheNearerCorner) {
  const auto mesh = unit_mesh(2);  // sides of 0.5
  auto phi = [](const Vec2& x) { return x.y() - 0.3; };  // 0.3 into the sides from y = 0
  const auto data = fsi::fe::cut_data(mesh, phi, fsi::fe::CutOptions{0.0, 0.4});
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (!mesh.is_corner[n]) continue;
    const double y = mesh.nodes[n].y();
    const int want = y == 0.5 ? 0 : (y < 0.5 ? -1 : 1);
    EXPECT_EQ(data.corner_sign[n], want) << "corner at y = " << y;
  }
}

}  // namespace

TEST(CutMesh, SnappingNeverPutsTheInterfaceOnAWallNode) {
  // The stairs' fan patches beside a riser: 5.6 cm long sides starting at the tread's
  // edge, a wall node. A cut 1.9 mm from it (3.4 % of the side) snaps onto a corner with
  // snap = 5e-2; onto a wall node it would be real contact, so it goes to 5 % of the side.
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{0.0, 0.112, 2, 0.0, 0.0}};
  b.y = {fsi::AxisPiece{0.0, 0.016, 2, 0.0, 0.0}};
  fsi::MeshSpec spec;
  spec.blocks = {b};
  const auto open = fsi::mesh::build_patch_mesh(spec, {});
  const auto walled = fsi::mesh::build_patch_mesh(spec, {fsi::Segment2{{0.0, 0.0}, {0.0, 0.016}}});
  auto phi = [](const Vec2& x) { return 0.0019 - x.x(); };  // fluid at the wall, solid beyond
  const fsi::fe::CutOptions options{5e-2, 0.0};
  const auto free_data = fsi::fe::cut_data(open, phi, options);
  const auto wall_data = fsi::fe::cut_data(walled, phi, options);
  int wall_nodes = 0;
  for (int n = 0; n < walled.num_nodes(); ++n) {
    if (!walled.is_corner[n] || walled.nodes[n].x() != 0.0) continue;
    ASSERT_TRUE(walled.on_wall[n]);
    ++wall_nodes;
    EXPECT_EQ(free_data.corner_sign[n], 0) << "without the wall the cut snaps onto the corner";
    EXPECT_EQ(wall_data.corner_sign[n], 1) << "the wall node stays in the fluid";
  }
  EXPECT_EQ(wall_nodes, 3);
  const CutMesh cut = fsi::fe::build_cut_mesh(walled, wall_data);
  ASSERT_FALSE(cut.interface.empty());
  for (const auto& seg : cut.interface) {
    EXPECT_NEAR(seg.a.x(), 0.05 * 0.056, 1e-12) << "5 % of the side from the wall";
    EXPECT_NEAR(seg.b.x(), 0.05 * 0.056, 1e-12);
  }
  EXPECT_NEAR(total_area(cut), 0.112 * 0.016, 1e-15);
}

TEST(CutMesh, ACutBesideAWallNodeInsideTheBodyGoesThroughIt) {
  // Example 1's ground row at rest in real contact: the ground node at x = 0 lies inside
  // the body, the interface meets the ground 1e-9 m beside it. Kept solid, that node left
  // solid slivers snap x side wide on the ground (2.5e-8 m on Example 1's sides, Newton
  // crawled and the contact steps started at residuals up to 1e6); being real contact
  // already, it is snapped onto: the interface goes through it, no sliver.
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{-0.05, 0.05, 4, 0.0, 0.0}};
  b.y = {fsi::AxisPiece{-1.0, -0.99375, 2, 0.0, 0.0}};
  fsi::MeshSpec spec;
  spec.blocks = {b};
  const auto mesh = fsi::mesh::build_patch_mesh(spec, {fsi::Segment2{{-1.0, -1.0}, {1.0, -1.0}}});
  // A V touching the ground at x = 0 from above, 1e-9 m into it: solid above the V.
  auto phi = [](const Vec2& x) { return -1e-9 + 0.1 * std::abs(x.x()) - (x.y() + 1.0); };
  const fsi::fe::CutOptions options{1e-6, 0.0};
  const auto data = fsi::fe::cut_data(mesh, phi, options);
  int contact_node = -1;
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.is_corner[n] && mesh.nodes[n].x() == 0.0 && mesh.nodes[n].y() == -1.0) contact_node = n;
  ASSERT_GE(contact_node, 0);
  ASSERT_TRUE(mesh.on_wall[contact_node]);
  ASSERT_LT(phi(mesh.nodes[contact_node]), 0.0) << "the ground node is inside the body";
  EXPECT_EQ(data.corner_sign[contact_node], 0) << "the interface goes through the ground node: still real contact";
  const CutMesh cut = fsi::fe::build_cut_mesh(mesh, data);
  double smallest = 1.0;
  for (const auto& e : cut.elements) smallest = std::min(smallest, std::abs(fsi::fe::element_area(cut, e)));
  EXPECT_GT(smallest, 1e-8) << "no sliver on the ground (a patch is 2.5e-2 x 3.1e-3 m)";
  EXPECT_NEAR(total_area(cut), 0.1 * 0.00625, 1e-15);
  // A ground node in the fluid still never gets the interface (the test above).
  const auto lifted = fsi::fe::cut_data(mesh, [&](const Vec2& x) { return phi(x) + 2e-9; }, options);
  EXPECT_EQ(lifted.corner_sign[contact_node], 1);
}

namespace {

/// The largest interior angle over all sub-elements [degrees].
double largest_angle_deg(const CutMesh& cut) {
  double worst = 0.0;
  for (const auto& e : cut.elements) worst = std::max(worst, fsi::fe::element_angle_range(cut, e)[1]);
  return worst * 180.0 / std::numbers::pi;
}

}  // namespace

TEST(CutMesh, AlignedCutsOnTheLongSidesOfAFlatPatchKeepItsAnglesBounded) {
  // A wall row like Example 1's and the campaign's: 8 cm x 3.125 mm. A body's bottom cuts
  // off the corner (0, 0): the long side at 0.45 L, the short side at half its height.
  constexpr double kL = 0.08, kH = 0.003125;
  const auto mesh = fsi::test::block_mesh(1, 1, kL, kH);
  auto phi = [](const Vec2& x) { return x.x() / (0.45 * kL) + x.y() / (0.5 * kH) - 1.0; };
  const CutMesh plain = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{1e-6, 0.0, 0.0});
  ASSERT_EQ(plain.kind[0], PatchKind::A);
  EXPECT_GT(largest_angle_deg(plain), 150.0) << "the fan of a flat patch";
  const CutMesh aligned = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{1e-6, 0.0, 0.1});
  ASSERT_EQ(aligned.kind[0], PatchKind::A);
  EXPECT_LT(largest_angle_deg(aligned), 95.0);
  EXPECT_NEAR(total_area(aligned), kL * kH, 1e-18);
  // The cut moved to the long side's midpoint; the interface there is within 0.1 kH of
  // the level set's zero (the short side's cut did not move).
  ASSERT_EQ(aligned.interface.size(), 1u);
  for (const Vec2& p : {aligned.interface[0].a, aligned.interface[0].b}) {
    const bool on_long_side = p.y() == 0.0;
    if (on_long_side) EXPECT_DOUBLE_EQ(p.x(), 0.5 * kL);
    else EXPECT_NEAR(phi(p), 0.0, 1e-12);
  }
}

TEST(CutMesh, ASteepCutOnALongSideStaysWhereItIs) {
  // The same row crossed upright at 0.3 L: moving that cut to the midpoint would move the
  // interface by 0.2 L = 1.6 cm, far more than 0.1 x the short side.
  constexpr double kL = 0.08, kH = 0.003125;
  const auto mesh = fsi::test::block_mesh(1, 1, kL, kH);
  auto phi = [](const Vec2& x) { return x.x() - 0.3 * kL; };
  const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{1e-6, 0.0, 0.1});
  ASSERT_EQ(cut.kind[0], PatchKind::B);
  for (const auto& s : cut.interface) {
    EXPECT_NEAR(phi(s.a), 0.0, 1e-15);
    EXPECT_NEAR(phi(s.b), 0.0, 1e-15);
  }
  EXPECT_LT(largest_angle_deg(cut), 95.0);
}

TEST(CutMesh, AFlatFanMovesItsCentreOnlyWithTheAlignmentOn) {
  // The wall row again, its corner (0, 0) cut off at t L on the long side and at half the
  // short side. The chapter's centre (alignment off) lies halfway between the interface's
  // midpoint and the opposite corner; with the alignment on, a fan with an angle above
  // 150 degrees may take a centre across from a cut, never a worse one.
  constexpr double kL = 0.08, kH = 0.003125;
  const auto mesh = fsi::test::block_mesh(1, 1, kL, kH);
  const auto& node = mesh.patches[0].node;
  int moved = 0;
  for (double t : {0.15, 0.3, 0.45, 0.6, 0.8}) {
    auto phi = [t](const Vec2& x) { return x.x() / (t * kL) + x.y() / (0.5 * kH) - 1.0; };
    const CutMesh chapter = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{1e-6, 0.0, 0.0});
    ASSERT_EQ(chapter.kind[0], PatchKind::A) << "t = " << t;
    const Vec2 centre = 0.5 * (0.5 * (chapter.x[node[1]] + chapter.x[node[3]]) + chapter.x[node[8]]);
    EXPECT_NEAR((chapter.x[node[4]] - centre).norm(), 0.0, 1e-15) << "t = " << t;
    const CutMesh ours = fsi::fe::build_cut_mesh(mesh, phi, fsi::fe::CutOptions{1e-6, 0.0, 0.1});
    EXPECT_LE(largest_angle_deg(ours), largest_angle_deg(chapter) + 1e-9) << "t = " << t;
    EXPECT_NEAR(total_area(ours), kL * kH, 1e-18);
    // Where the cuts stayed (the alignment moves t = 0.45 to the midpoint), the centre
    // alone can have moved.
    if (ours.x[node[1]] == chapter.x[node[1]] && ours.x[node[3]] == chapter.x[node[3]])
      moved += (ours.x[node[4]] - chapter.x[node[4]]).norm() > 0.0;
  }
  EXPECT_GT(moved, 0) << "no fan took another centre";
}

TEST(CutMesh, AContactLineOnAWallMovesTwiceAsFarToItsMidpoint) {
  // The wall row with the wall along its bottom. A body touches the wall left of x_c =
  // 0.35 L, and a wedge of fluid opens to the right under it, 0.7 H high at the right side.
  // Moving the cut on the bottom to the midpoint moves the interface by 0.16 H: more than
  // 0.1 H, within twice that. On the wall the cut moves; the same cut off the wall stays.
  constexpr double kL = 0.08, kH = 0.003125, kXc = 0.35 * kL, kSlope = 0.7 * kH / (kL - kXc);
  auto phi = [](const Vec2& x) { return kSlope * (x.x() - kXc) - x.y(); };
  const fsi::fe::CutOptions options{1e-6, 0.0, 0.1};
  const auto on_wall = fsi::test::block_mesh(1, 1, kL, kH, false, {}, 0, {fsi::Segment2{{0.0, 0.0}, {kL, 0.0}}});
  const auto off_wall = fsi::test::block_mesh(1, 1, kL, kH);
  ASSERT_TRUE(on_wall.on_wall[on_wall.patches[0].node[0]] && on_wall.on_wall[on_wall.patches[0].node[2]]);
  auto bottom_cut = [&](const fsi::mesh::PatchMesh& mesh) {
    const CutMesh cut = fsi::fe::build_cut_mesh(mesh, phi, options);
    EXPECT_EQ(cut.kind[0], PatchKind::A);
    return cut.x[mesh.patches[0].node[1]].x();
  };
  EXPECT_DOUBLE_EQ(bottom_cut(on_wall), 0.5 * kL);
  EXPECT_NEAR(bottom_cut(off_wall), kXc, 1e-15);
}
