// The note a broken body's report gets when it broke on a row of wall patches much wider
// than thick (core/flat_wall_rows.hpp), on Example 1's mesh: its floor rows are 3.1 mm
// thick and 2.5 cm wide under the ball, growing to 10 cm at the open sides.
#include "core/flat_wall_rows.hpp"

#include <gtest/gtest.h>

#include "fsi/scenario.hpp"
#include "mesh/patch_mesh.hpp"

namespace {

fsi::mesh::PatchMesh example1_mesh() {
  const fsi::Scenario s = fsi::example1_scenario();
  return fsi::mesh::build_patch_mesh(s.mesh, s.walls);
}

TEST(FlatWallRows, UnderExample1sBallTheRowsAreNarrowEnough) {
  const fsi::mesh::PatchMesh mesh = example1_mesh();
  const fsi::core::WallRow row = fsi::core::widest_wall_row_near(mesh, {0.01, -0.999});
  EXPECT_EQ(row.wall, 0);
  EXPECT_NEAR(row.thickness_m, 0.003125, 1e-9);
  EXPECT_GE(row.aspect, 8.0 - 1e-9);  // its own column, 2.5 cm
  EXPECT_LT(row.aspect, fsi::core::kFlatWallRowAspect);
  EXPECT_TRUE(fsi::core::flat_wall_row_note(mesh, {0.01, -0.999}).empty());
}

TEST(FlatWallRows, NearTheOpenSidesTheNoteNamesTheRow) {
  const fsi::mesh::PatchMesh mesh = example1_mesh();
  const fsi::core::WallRow row = fsi::core::widest_wall_row_near(mesh, {0.9, -0.998});
  EXPECT_EQ(row.wall, 0);
  EXPECT_GT(row.aspect, 28.0);  // 9.5-10 cm by 3.1 mm
  const std::string note = fsi::core::flat_wall_row_note(mesh, {0.9, -0.998});
  EXPECT_NE(note.find("wall 0's row of patches is 3"), std::string::npos) << note;
  EXPECT_NE(note.find("at most 16 times"), std::string::npos) << note;
}

TEST(FlatWallRows, AwayFromTheWallsOrOutsideTheMeshThereIsNoNote) {
  const fsi::mesh::PatchMesh mesh = example1_mesh();
  EXPECT_EQ(fsi::core::widest_wall_row_near(mesh, {0.9, -0.5}).wall, -1);  // mid-fluid
  EXPECT_EQ(fsi::core::widest_wall_row_near(mesh, {3.0, 0.0}).wall, -1);   // outside
  EXPECT_TRUE(fsi::core::flat_wall_row_note(mesh, {0.9, -0.5}).empty());
}

}  // namespace
