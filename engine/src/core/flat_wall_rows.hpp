#pragma once
/// \file flat_wall_rows.hpp
/// Whether a place where a body broke lies on a row of wall patches much wider along the
/// wall than thick, and a note for the step report that says so: the mesh, not the
/// solver settings, is then what to change.
///
/// Evidence (docs/solver.md, "Flat rows at a wall"): heavy balls of the campaign's
/// envelope that landed on rows 3.1 mm thick and 7-10 cm wide (aspect 21-32) were turned
/// inside out in the landing; the same landings on rows at most 5 cm wide (aspect 16)
/// converged every step.
#include <string>

#include "fsi/field_view.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// Rows beside a wall wider than this many times their thickness draw the note (the
/// widest rows the probed landings held on; Example 1's ball lands on rows of aspect 8-11).
inline constexpr double kFlatWallRowAspect = 16.0;

/// The widest wall row, as width over thickness, among the patches within one patch of
/// `where_m` (the patch holding it in the reference mesh and its neighbours) that have a
/// side on a wall; 0 if none has, or if no patch holds the place.
struct WallRow {
  double aspect = 0.0;
  double width_m = 0.0;      ///< the patch side on the wall
  double thickness_m = 0.0;  ///< the patch's extent across the wall
  int wall = -1;
};
WallRow widest_wall_row_near(const mesh::PatchMesh& mesh, Point2 where_m);

/// "; there wall N's row of patches is 21 times as wide as thick (...)" where that row's
/// aspect exceeds kFlatWallRowAspect, empty otherwise.
std::string flat_wall_row_note(const mesh::PatchMesh& mesh, Point2 where_m);

}  // namespace fsi::core
