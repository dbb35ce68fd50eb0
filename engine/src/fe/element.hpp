#pragma once
/// \file element.hpp
/// Shape functions and quadrature on the sub-elements of a CutMesh.
///
/// Sub-quads are bilinear isoparametric (Q1) elements, sub-triangles linear (P1).
/// Quadrature: 2x2 Gauss per quad, the 3-point degree-2 rule per triangle (exact for
/// the P1 mass matrix; docs/method.md, "The discrete space").
#include <array>
#include <vector>

#include "fe/cut_mesh.hpp"

namespace fsi::fe {

/// Values and physical gradients of an element's shape functions at one point.
struct ShapeValues {
  int n = 0;                      ///< number of shape functions (3 or 4)
  std::array<double, 4> value{};  ///< N_i(x)
  std::array<Vec2, 4> grad{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  ///< grad N_i [1/m]
};

struct QuadraturePoint : ShapeValues {
  Vec2 x = Vec2::Zero();  ///< physical position [m]
  double weight = 0.0;    ///< quadrature weight times |det J| [m^2]
};

/// Shape values at reference coordinates (xi, eta): quads use [0,1]^2 with corners
/// counter-clockwise from (0,0); triangles barycentric (xi, eta) = (lambda_1, lambda_2).
ShapeValues shape_at_reference(const CutMesh& cut, const SubElement& e, double xi, double eta);

/// Reference coordinates of the point at parameter s in [0,1] along local edge i of e
/// (from vertex i to vertex i + 1, counter-clockwise).
std::array<double, 2> edge_reference(const SubElement& e, int i, double s);

/// Appends the quadrature points of one element.
void append_quadrature(const CutMesh& cut, const SubElement& e, std::vector<QuadraturePoint>& out);

/// Reference coordinates of a physical point for an element (Newton for quads).
/// Returns false if the inverse map failed to converge.
bool reference_coordinates(const CutMesh& cut, const SubElement& e, const Vec2& x, double& xi,
                           double& eta);

/// How far inside the element the reference point is: >= 0 inside, < 0 outside.
double inside_margin(const SubElement& e, double xi, double eta);

/// Quadrature points of all elements of a cut mesh, flat: element i owns
/// [first[i], first[i+1]).
struct QuadratureTable {
  std::vector<QuadraturePoint> points;
  std::vector<int> first;
};
QuadratureTable build_quadrature(const CutMesh& cut);

}  // namespace fsi::fe
