#pragma once
/// \file initial_guess.hpp
/// Newton's start for a step: the current solution, carried over to the new mesh.
///
/// The nodes of a cut patch move with the interface, so a coefficient of the current
/// solution may belong to another place on the new mesh: a moved node is re-interpolated
/// at its new position. A node the body newly covers needs more: interpolated there it
/// would carry the fluid's harmonic extension of the displacement, which near the
/// interface differs from the solid's field by up to a few millimetres (and so may the
/// value of a node that touched the body only through slivers). On a thin solid
/// sub-element (a 1.8 mm side, the stairs at t = 8.39 s) that difference is a gradient
/// error of order one: det(I - grad u) <= 0, Jacobian entries of 1e15, and Newton cannot
/// move at all (session 15). So v and u of such a node are extrapolated from the solid
/// field of its patch (its largest solid sub-element, since extrapolating a sliver
/// magnifies the sliver's own errors); for a rigid motion, a linear field, that is exact.
#include <Eigen/Core>

#include "fe/point_locator.hpp"

namespace fsi::core {

struct InitialGuessStats {
  int moved_nodes = 0;         ///< re-interpolated at their new positions
  int extrapolated_nodes = 0;  ///< solid on the new mesh, in a fluid sub-element of the current one
};

/// The start x for Newton on `next`, given the solution on `current`. Wall nodes keep
/// their (zero) velocity.
Eigen::VectorXd initial_guess(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                              const fe::CutMesh& current, const fe::CutMesh& next,
                              const Eigen::VectorXd& solution, InitialGuessStats* stats = nullptr);

}  // namespace fsi::core
