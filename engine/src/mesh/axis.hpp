#pragma once
/// \file axis.hpp
/// Patch lines of one mesh direction from graded axis pieces (fsi::AxisPiece).
#include <vector>

#include "fsi/scenario.hpp"

namespace fsi::mesh {

/// Sorted patch-line coordinates [m] of the union of `pieces` (shared end points
/// merged). Throws std::invalid_argument if the pieces overlap or leave gaps.
std::vector<double> axis_lines(const std::vector<AxisPiece>& pieces);

/// Positions of one piece, from `from_m` to `to_m` inclusive (patches + 1 values).
///
/// x(t) = from + L (c t + (1 - c) t^q), t = i/n: the first patch has size ~ L c / n and
/// the last L (1 - (c (1 - 1/n) + (1 - c)(1 - 1/n)^q)); c comes from `first_m`, q is
/// found by bisection so that the last patch has size `last_m` (q = 1: uniform,
/// q = 2: linearly growing patch sizes as in the chapter's x direction).
std::vector<double> piece_lines(const AxisPiece& piece);

/// Inserts the midpoint of every interval `times` times (global refinement).
std::vector<double> refine_lines(std::vector<double> lines, int times);

}  // namespace fsi::mesh
