#pragma once
/// \file rereference.hpp
/// Taking the body's rigid motion out of the displacement (ours).
///
/// The chapter's Eulerian solid carries u with X = x - u(x) the initial point of x, and the
/// Initial Point Set finds the body as {x : d0(x - u(x)) < 0}. After the ball has rolled by
/// an angle theta, u = x - Q^T (x - c) - c0 + (elastic part) has the gradient I - Q^T, of
/// size 2 sin(theta/2), in the solid. Its harmonic extension into the fluid (docs/method.md,
/// natural conditions at the walls) must turn that gradient into a zero normal derivative
/// at each wall within the gap between body and wall: millimetres on the stairs' treads,
/// centimetres at a riser's corner. There x - u(x) is far from the rigid continuation,
/// so the level set on the fluid side of the interface, Newton's start for newly covered
/// nodes (initial_guess.hpp's "repair") and the IPS mapping go wrong; the stairs runs failed
/// after about 8 s of rolling, never before.
///
/// Re-referencing replaces the initial configuration by the initial ball moved rigidly
/// with the body: X' = Q (X - Xm) + xm, with Q and (Xm, xm) the least-squares rigid fit of
/// the solid's nodes' initial points onto their positions, and u' = x - X'. For the ball
/// d0 is rotation invariant, so the level set is unchanged: d0'(x - u') = d0(x - u). So are
/// the Cauchy stress (F' = F Q^T, an isotropic St. Venant-Kirchhoff material), the density
/// (det F' = det F) and the displacement equation (its residual turns by Q). Both time
/// levels take the same map (u^{m-1} enters the next step's time derivative). In the
/// fluid the affine image of the old extension no longer meets the natural wall condition;
/// the next step's Newton solves the extension rows afresh, to the small extension of the
/// elastic part: that, not the physics, is what changes.
#include <vector>

#include <Eigen/Core>

#include "fe/cut_mesh.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// X' = Q(angle) (X - from_mean) + to_mean, Q the counter-clockwise rotation.
struct RigidFit {
  double angle_rad = 0.0;
  mesh::Vec2 from_mean = mesh::Vec2::Zero();  ///< mean initial point X of the nodes used
  mesh::Vec2 to_mean = mesh::Vec2::Zero();    ///< their mean position x
  int nodes = 0;                              ///< nodes inside the solid (0: no fit)
};

/// Least-squares rigid motion taking the initial points X = x - u(x) of the nodes inside
/// the solid (solid sub-elements only) of `cut` onto their positions x; with `nodes`, only
/// those it marks (one body of several: body_nodes).
RigidFit fit_rigid_motion(const fe::CutMesh& cut, const Eigen::VectorXd& solution,
                          const std::vector<char>* nodes = nullptr);

/// The nodes of `cut` that belong to a solid sub-element of body `body` (element_body:
/// interface::element_bodies of `cut`).
std::vector<char> body_nodes(const fe::CutMesh& cut, const std::vector<int>& element_body, int body);

/// u' = x - (Q (x - u - from_mean) + to_mean) at every node (positions of `cut`, the
/// mesh of that level: moved nodes at their moved place). Affine in x and u, so exact for
/// the finite element functions, not only at the nodes.
/// With `nodes`, only at the nodes it marks (one body's region of several).
void rereference_displacement(const fe::CutMesh& cut, const RigidFit& fit, Eigen::VectorXd& solution,
                              const std::vector<char>* nodes = nullptr);

/// The reference ball's centre c moved by the same map: Q (c - from_mean) + to_mean.
mesh::Vec2 rereferenced_point(const RigidFit& fit, const mesh::Vec2& c);

}  // namespace fsi::core
