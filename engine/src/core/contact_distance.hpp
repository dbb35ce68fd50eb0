#pragma once
/// \file contact_distance.hpp
/// The distance the penalty contact pressure P_c (Sect. 12.5) is evaluated with.
///
/// The chapter's P_c = gamma_c (dist_0 - dist)/dist acts on the interface points closer
/// than dist_0 to a wall. Under a flat wall the gap along a round body grows
/// quadratically, d + s^2/(2R), so the pressure acts on an arc 2 sqrt(2 R dist_0) long
/// (18 cm for the stairs' ball, R = 0.4 m, dist_0 = 1 cm). At a convex wall corner (a
/// tread's edge) the gap to the corner point grows linearly, sqrt(d^2 + s^2), the arc
/// shrinks to 2 dist_0, and at a 2 mm gap the corner pushes with a tenth of the flat
/// wall's force (28 N/m against 3.2 kN/m for gamma_c = 1e4): far less than the weight
/// of a ball rolling over the edge, which then reaches the corner (real contact), sticks
/// to it through the no-slip wall node and is torn apart (three of the four stairs runs
/// at tread 2's edge, docs/method.md "Corners push like walls").
///
/// So here every wall end point the body has come within dist_0 of stands for a flat
/// wall through it, tangent to the body: the line through the corner perpendicular to
/// the direction from the corner to the body's centroid (for a ball, the tangent where it
/// is nearest the corner). The chord of the interface nearest to the corner would give a
/// tangent too, but the contact pressure dents the body there, that chord tilts by some
/// degrees and its neighbours fall behind the line (distance 0, P_c at its bound: a
/// tenfold force in one step, and Newton fails). An interface point
/// within `window_m` of the corner is as far from the walls as the nearer of the real
/// walls and that line. For a convex body this gives the flat wall's pressure profile at
/// the same gap; it only ever shortens distances, so a flat wall, a concave corner (never
/// nearest to a body point) and everything beyond dist_0 stay as they were.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fe/cut_mesh.hpp"
#include "fsi/field_view.hpp"

namespace fsi::core {

/// The line through a wall corner tangent to a body: perpendicular to the direction from
/// the corner to the body's centroid (for a ball, the tangent where it is nearest the
/// corner). Both the contact force's corners and the corner barrier (corner_barrier.hpp)
/// measure their gap to it.
struct CornerLine {
  Eigen::Vector2d corner;
  Eigen::Vector2d normal;  ///< unit, from the corner towards the body

  /// The line of `corner` when the body's `interface` comes within `reach_m` of it
  /// (none: farther, or the centroid on the corner).
  static std::optional<CornerLine> within_reach(const Eigen::Vector2d& corner,
                                                const std::vector<fe::InterfaceSegment>& interface,
                                                const Eigen::Vector2d& body_centroid, double reach_m);

  /// The distance of x from the line on the body's side (0 behind it) for x within
  /// `window_m` of the corner; infinity beyond the window.
  double distance_m(const Eigen::Vector2d& x, double window_m) const;
};

class ContactDistance {
 public:
  /// `reach_m`: dist_0, corners farther than this from the interface push nothing;
  /// `window_m`: how far from its corner a tangent line reaches (the body's radius);
  /// `corners_as_walls` false: the plain distance to the walls (the chapter, literally).
  /// `body_centroid`: the solid's centroid [m].
  ContactDistance(const std::vector<Segment2>& walls, const std::vector<fe::InterfaceSegment>& interface,
                  const Eigen::Vector2d& body_centroid, double reach_m, double window_m, bool corners_as_walls);

  /// Distance from the interface point x to the walls for P_c [m].
  double operator()(const Eigen::Vector2d& x) const;

  /// How many corners stand for a wall this step.
  int num_corner_walls() const { return static_cast<int>(corner_walls_.size()); }

 private:
  const std::vector<Segment2>& walls_;
  std::vector<CornerLine> corner_walls_;
  double window_m_;
};

}  // namespace fsi::core
