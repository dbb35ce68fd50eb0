#pragma once
/// \file walls.hpp
/// Distances to the no-slip walls (segments of Scenario::walls). Contact (Sect. 12.5),
/// the identity gap of T_m, the distance functionals and the mesher's wall marking all
/// measure "distance to the nearest wall" the same way, so it lives here once.
#include <vector>

#include <Eigen/Core>

#include "fsi/field_view.hpp"

namespace fsi::mesh {

/// The nearest wall point to some x.
struct WallDistance {
  double distance_m;     ///< |x - nearest|, +infinity without walls
  int wall = -1;         ///< index into the walls, -1 without walls
  Eigen::Vector2d nearest{0.0, 0.0};  ///< nearest point on that wall [m]
};

/// Nearest point of one segment to x: the foot of the perpendicular, or an end point
/// when the foot falls outside the segment (distance to a corner is then Euclidean).
Eigen::Vector2d nearest_on_segment(const Segment2& segment, const Eigen::Vector2d& x);

/// Distance from x to one segment [m].
double distance_to_segment(const Segment2& segment, const Eigen::Vector2d& x);

/// Nearest wall to x (the first one on ties).
WallDistance distance_to_walls(const std::vector<Segment2>& walls, const Eigen::Vector2d& x);

}  // namespace fsi::mesh
