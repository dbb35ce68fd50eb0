#pragma once
/// \file field_view.hpp
/// The plain mesh-and-fields view of one time level: the only thing a renderer or
/// exporter sees of the engine. Everything is copied out, so a FieldView stays valid
/// after the engine steps on.
///
/// The triangles are the sub-elements of the locally modified discretization (each
/// sub-quad split in two), with the node positions the solver used, so a picture of a
/// cut patch shows exactly what was computed. Nodal values are the FE coefficients
/// (the space is piecewise linear on these triangles, bilinear on the sub-quads).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fsi {

struct Point2 {
  double x = 0.0;  ///< [m]
  double y = 0.0;  ///< [m]
};

/// A straight piece of a wall or of the interface.
struct Segment2 {
  Point2 a, b;
};

/// Phase of a sub-element.
enum class Phase : std::uint8_t { fluid = 0, solid = 1 };

struct FieldView {
  double time_s = 0.0;  ///< simulated time t_m [s]
  long step = 0;        ///< time step index m

  std::vector<Point2> nodes;                   ///< node positions [m], one per node
  std::vector<std::array<int, 3>> triangles;   ///< node indices, counter-clockwise
  std::vector<Phase> triangle_phase;           ///< one per triangle
  /// One per triangle: the body (0 = body1, 1 = body2, ...) of a solid one, -1 for fluid
  /// (empty: not known; then every solid triangle is body1's).
  std::vector<int> triangle_body;
  /// Patch outlines and sub-element edges for a mesh overlay: pairs of node indices.
  std::vector<std::array<int, 2>> mesh_edges;

  // Nodal fields, one value per node.
  std::vector<double> vx;  ///< velocity x [m/s]
  std::vector<double> vy;  ///< velocity y [m/s]
  std::vector<double> p;   ///< pressure [Pa] (inside the solid: its harmonic extension)
  std::vector<double> ux;  ///< displacement x [m] (inside the fluid: its harmonic extension)
  std::vector<double> uy;  ///< displacement y [m]

  /// The discrete interface: a set of segments (the polyline pieces of each cut patch).
  std::vector<Segment2> interface;
  /// One per interface segment: the body it bounds (0 = body1; empty: body1 everywhere).
  std::vector<int> interface_body;
  /// The no-slip walls of the domain.
  std::vector<Segment2> walls;

  /// Bounding box of the domain [m].
  Point2 domain_min, domain_max;
};

}  // namespace fsi
