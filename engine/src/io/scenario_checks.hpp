#pragma once
/// \file scenario_checks.hpp
/// The parts of validate(): every value against its rule (scenario_validate.cpp), then
/// the relations between values (geometry_checks.cpp).
#include "fsi/scenario.hpp"
#include "io/scenario_rules.hpp"

namespace fsi::io {

/// Largest mesh accepted (nodes summed over blocks, after refinement): beyond this the
/// direct solver needs more memory than the machines this runs on have.
inline constexpr double kMaxNodes = 2.0e6;

/// Nodes of a block after `refinements` global refinements (9 nodes per patch).
double block_node_count(const BlockSpec& block, int refinements);

/// Axis pieces tile an interval, grading is possible, mapped blocks are proper quads,
/// the mesh is not too large. Assumes the per-value rules hold.
void check_mesh(const MeshSpec& mesh, const KeyPath& at);

/// Walls have a length; the ball lies inside the domain and touches no wall.
void check_body_and_walls(const Scenario& scenario, const KeyPath& at);

}  // namespace fsi::io
