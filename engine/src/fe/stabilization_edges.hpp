#pragma once
/// \file stabilization_edges.hpp
/// Interior edges of a cut mesh with what the anisotropic CIP pressure stabilization
/// (Sect. 12.2) needs: the two neighbouring sub-elements, their cell sizes normal to
/// the edge (h_n = |K|/|e| for parallelogram quads, 2|K|/|e| for triangles), whether
/// the edge belongs to E_h^i (an edge of a triangle, i.e. of a cut patch) or to
/// E_h^0 (between two quads), and shape gradients of both sides at 2 Gauss points.
#include <array>
#include <vector>

#include "fe/element.hpp"

namespace fsi::fe {

struct StabilizationEdge {
  int element1 = -1, element2 = -1;
  double length_m = 0.0;
  double hn1_m = 0.0, hn2_m = 0.0;  ///< cell sizes normal to the edge [m]
  bool in_cut_patch = false;        ///< E_h^i (averaged form) vs E_h^0 (jump form)
  std::array<double, 2> weight{};   ///< Gauss weights times the edge length [m]
  std::array<ShapeValues, 2> side1, side2;  ///< shape values of element1/2 at the points
};

std::vector<StabilizationEdge> build_stabilization_edges(const CutMesh& cut);

}  // namespace fsi::fe
