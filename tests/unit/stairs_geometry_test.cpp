// The stairs scenarios (Example 2): the nine blocks merge into one conforming mesh whose
// boundary is exactly the walls plus the open top, with fine rows on every landing zone.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "fsi/scenario.hpp"
#include "mesh/patch_mesh.hpp"
#include "mesh/walls.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kStairs = fs::path(FSI_SOURCE_DIR) / "assets" / "scenarios" / "stairs";

void expect_closed_box_with_open_top(const fsi::Scenario& s) {
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  ASSERT_EQ(s.walls.size(), 8u);
  const double top = mesh.max.y();
  double open_length = 0.0;
  for (const fsi::mesh::GridEdge& e : mesh.edges) {
    if (!e.boundary) continue;
    const auto& a = mesh.nodes[e.a];
    const auto& b = mesh.nodes[e.b];
    if (e.wall >= 0) continue;
    // A boundary edge that is no wall must be on the open top: anything else is a gap
    // between blocks that did not merge (it would act as an open boundary inside).
    EXPECT_NEAR(a.y(), top, 1e-12) << "open edge at (" << a.x() << ", " << a.y() << ")";
    EXPECT_NEAR(b.y(), top, 1e-12) << "open edge at (" << b.x() << ", " << b.y() << ")";
    open_length += (b - a).norm();
  }
  EXPECT_NEAR(open_length, mesh.max.x() - mesh.min.x(), 1e-9) << "the whole top is open";
  // Every wall is covered by boundary edges over its full length.
  std::vector<double> covered(s.walls.size(), 0.0);
  for (const fsi::mesh::GridEdge& e : mesh.edges)
    if (e.boundary && e.wall >= 0) covered[e.wall] += (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    EXPECT_NEAR(covered[w], std::hypot(wall.b.x - wall.a.x, wall.b.y - wall.a.y), 1e-9) << "wall " << w;
  }
}

TEST(StairsGeometry, BlocksMergeIntoABoxWithAnOpenTop) {
  const fsi::Scenario s = fsi::load_scenario(kStairs / "stairs_rho1000.json");
  expect_closed_box_with_open_top(s);
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  EXPECT_GT(mesh.num_nodes(), 5000);
  EXPECT_LT(mesh.num_nodes(), 15000);
  expect_closed_box_with_open_top(fsi::load_scenario(fs::path(FSI_SOURCE_DIR) / "tests" / "data" / "stairs_coarse.json"));
}

TEST(StairsGeometry, FineRowsOnThePlaneAndTheTreads) {
  const fsi::Scenario s = fsi::load_scenario(kStairs / "stairs_rho1000.json");
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  // Walls 1 (plane), 2, 4, 6 (treads): the patches along them are at most 5 mm thick,
  // half of dist_0, so the penalty force acts over at least two rows.
  std::vector<double> thickest(s.walls.size(), 0.0);
  for (const fsi::mesh::Patch& p : mesh.patches)
    for (int side = 0; side < 4; ++side) {
      const int wall = mesh.edges[p.edge[side]].wall;
      if (wall >= 0) thickest[wall] = std::max(thickest[wall], p.min_size_m);
    }
  for (int w : {1, 2, 4, 6}) {
    EXPECT_GT(thickest[w], 0.0) << "wall " << w;
    EXPECT_LE(thickest[w], 0.5 * s.contact.dist0_m + 1e-12) << "wall " << w;
  }
  // The ball starts above the plane with a 0.45 m gap, 0.2 m from the left wall.
  const Eigen::Vector2d c(s.body.center_m.x, s.body.center_m.y);
  EXPECT_GT(fsi::mesh::distance_to_segment(s.walls[1], c) - s.body.radius_m, 0.4);
  EXPECT_NEAR(fsi::mesh::distance_to_walls(s.walls, c).distance_m - s.body.radius_m, 0.2, 1e-12);
  EXPECT_EQ(fsi::mesh::distance_to_walls(s.walls, c - Eigen::Vector2d(0, 1)).wall, 1);
}

/// The largest side ratio of the patches farther than `from_walls_m` from every wall.
double flattest_patch_in_open_fluid(const fsi::Scenario& s, double from_walls_m) {
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  double flattest = 1.0;
  for (const fsi::mesh::Patch& p : mesh.patches) {
    const Eigen::Vector2d centre = mesh.nodes[p.node[4]];
    if (fsi::mesh::distance_to_walls(s.walls, centre).distance_m > from_walls_m)
      flattest = std::max(flattest, p.size_m / p.min_size_m);
  }
  return flattest;
}

TEST(StairsGeometry, ThinRowsEndBesideTheRisers) {
  // A tread's 4 mm rows fan out to coarse rows within the fan block beside the riser
  // below it (BlockSpec::y_right): the flattest patches are in the fans, flatter the
  // closer to the riser's top corner (6 at 0.15 m from it, 3.4 at 0.3 m). Without the fans
  // the rows go on over the lower treads as 4 mm x 6 cm patches (ratio 15) at any
  // distance from the walls, where each ball going down a step stalled Newton.
  for (const char* file : {"stairs_rho1000.json", "../../../tests/data/stairs_coarse.json"}) {
    SCOPED_TRACE(file);
    const fsi::Scenario s = fsi::load_scenario(kStairs / file);
    EXPECT_LT(flattest_patch_in_open_fluid(s, 0.15), 6.5);
    EXPECT_LT(flattest_patch_in_open_fluid(s, 0.3), 4.0);
    EXPECT_LT(flattest_patch_in_open_fluid(s, 0.5), 3.0);
  }
}

TEST(StairsGeometry, ScenariosDifferOnlyInFluidDensityAndContact) {
  struct Case {
    const char* file;
    double rho_f, gamma_c;
  };
  for (const Case& c : {Case{"stairs_rho100.json", 100, 1e4}, Case{"stairs_rho150.json", 150, 1e4},
                        Case{"stairs_rho300.json", 300, 5e3}, Case{"stairs_rho1000.json", 1000, 5e3},
                        Case{"stairs_rho150_g5e3.json", 150, 5e3}, Case{"stairs_rho150_g2e4.json", 150, 2e4}}) {
    SCOPED_TRACE(c.file);
    fsi::Scenario s = fsi::load_scenario(kStairs / c.file);
    EXPECT_EQ(s.fluid.density_kgpm3, c.rho_f);
    EXPECT_EQ(s.contact.gamma_c, c.gamma_c);
    EXPECT_EQ(s.contact.dist0_m, 1e-2);
    // Everything else is the rho_f = 1000 scenario's (material of Example 1).
    fsi::Scenario ref = fsi::load_scenario(kStairs / "stairs_rho1000.json");
    ref.fluid.density_kgpm3 = c.rho_f;
    ref.contact.gamma_c = c.gamma_c;
    EXPECT_EQ(fsi::fingerprint(s), fsi::fingerprint(ref));
    EXPECT_EQ(s.solid.mu_pa, 2e5);
    EXPECT_EQ(s.solid.lambda_pa, 8e5);
  }
}

}  // namespace
