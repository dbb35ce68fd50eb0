#pragma once
/// \file initial_guess.hpp
/// Newton's start for a step: the current solution, carried over to the new mesh.
///
/// The nodes of a cut patch move with the interface, so a coefficient of the current
/// solution may belong to another place on the new mesh: a moved node is re-interpolated
/// at its new position. A node the body newly covers may need more: interpolated in a
/// fluid sub-element it carries the fluid's harmonic extension of the displacement, which
/// near the interface differs from the solid's field by up to millimetres. On a thin solid
/// sub-element (a 1.8 mm side, the stairs at t = 8.39 s) that is a gradient error of order
/// one: det(I - grad u) <= 0, Jacobian entries of 1e15, and Newton cannot move at all.
/// Such nodes take v and u continued from the solid field of their patch
/// (linear for triangles, bilinear for quads: exact for a rigid motion).
///
/// Where: `repair_unphysical` (the engine's start) only at the nodes of solid
/// sub-elements that the interpolated start deforms beyond any physical state (det(I -
/// grad u) outside [1/2, 2]); `solid_field` at every node in the body that lay in a fluid
/// sub-element. Beside tread 1's corner (rho_f = 100, t = 8.151 s) only the latter lets
/// plain Newton converge (the fluid's values were off by 0.4 mm, physical enough), but as
/// the engine's start it broke the real-contact test and slowed Example 1's steps, and a
/// retry from it after a failed attempt broke the real-contact test too: it
/// is tools/fsi-newton-probe's `--start solid` until that is understood. Never in
/// patches cut as before (the last step solved on those sub-elements).
#include <limits>

#include <Eigen/Core>

#include "fe/point_locator.hpp"

namespace fsi::core {

struct InitialGuessStats {
  int moved_nodes = 0;         ///< re-interpolated at their new positions
  int extrapolated_nodes = 0;  ///< continued from the solid field
};

/// det(I - grad u) of the solid's deformation at a point of sub-element e with shape
/// values s, for coefficients x (node-major, kFieldsPerNode per node).
double deformation_determinant(const fe::SubElement& e, const fe::ShapeValues& s, const Eigen::VectorXd& x);

/// det(I - grad u) over the solid quadrature points of a cut mesh: its smallest value,
/// where, and at how many points it is <= 0 (the deformation turned inside out).
struct SolidDeterminant {
  double smallest = std::numeric_limits<double>::infinity();  ///< infinity without a solid
  mesh::Vec2 where = mesh::Vec2::Zero();                        ///< [m]
  int non_positive = 0;
};
SolidDeterminant solid_determinant(const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                   const Eigen::VectorXd& x);

enum class StartMode {
  interpolated,       ///< re-interpolation only (the engine's former start)
  repair_unphysical,  ///< + the solid field where the start is unphysical
  solid_field         ///< + the solid field at every node in the body that lay in the fluid
};

/// The start x for Newton on `next`, given the solution on `current`. Wall nodes keep
/// their (zero) velocity.
Eigen::VectorXd initial_guess(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                              const fe::CutMesh& current, const fe::CutMesh& next,
                              const Eigen::VectorXd& solution, InitialGuessStats* stats = nullptr,
                              StartMode mode = StartMode::repair_unphysical);

}  // namespace fsi::core
