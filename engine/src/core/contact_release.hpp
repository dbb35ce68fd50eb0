#pragma once
/// \file contact_release.hpp
/// Which wall nodes inside the body let the solid go this step (real contact).
///
/// At a no-slip wall node v = 0, and the solid's displacement equation
/// d_t u + v.grad u = v then keeps u, and with it the interface d0(x - u(x)), where it
/// is: a body that touches a wall stays held there for good. That is right for a body
/// pressed onto the wall, and it breaks a body that rebounds: the rest of it moves away
/// from the points the wall holds until the solid turns inside out (docs/validation.md,
/// "Real contact at speed"). At a released node the u row is the harmonic extension of
/// the solid's displacement around it instead (forms::ElementInput::u_row_released), so the
/// interface there follows the solid away from the wall; v stays 0 (no slip).
///
/// The solid is released where the wall pulls it (a contact can push, not pull), one
/// contact patch at a time: the wall nodes touching the solid along one wall, joined by
/// wall edges. The force the wall exerts at a node is read from the momentum rows of the
/// residual at the step's start without the no-slip rows
/// (FsiSystem::unconstrained_residual); a patch is released when the sum of those forces
/// along its inward normal pulls, and a node when every patch through it (two at a
/// corner) is. Node by node, the stiff ball of assets/scenarios/impacts/ rebounding from
/// its third landing chattered (the forces at single nodes change sign from step to step
/// while the patch as a whole still presses) and Newton failed at t = 2.29 s; by patches
/// it rebounds from there, lands a fourth time and rests, every step to t = 3 s converged.
#include <vector>

#include <Eigen/Core>

#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// released[n] = 1 for the wall nodes n that touch the solid (touches_solid, on the step's
/// geometry) and lie only in contact patches that the wall force (`wall_force` [N/m],
/// kFieldsPerNode entries per node, the momentum ones read) pulls as a whole. A patch with
/// a node that did not touch the solid at the step's start (touched_solid) is held: the
/// node's rows there were not the solid's (the stiff ball of RealContact.* "pulled" with
/// -4e5 N/m at the rim of its first touch), and the patch grows. Empty when no node is
/// released.
std::vector<char> released_wall_nodes(const mesh::PatchMesh& mesh, const std::vector<char>& touches_solid,
                                      const std::vector<char>& touched_solid, const Eigen::VectorXd& wall_force);

/// The hold turned round: the wall nodes touching the solid that `released` (as
/// released_wall_nodes returns it, empty for none) holds are released and the released
/// held. For the retry of a step that did not converge in real contact. Empty when no
/// node is released.
std::vector<char> turned_round(const mesh::PatchMesh& mesh, const std::vector<char>& touches_solid,
                               const std::vector<char>& released);

}  // namespace fsi::core
