#pragma once
/// \file contact_release.hpp
/// Which wall nodes inside the body let the solid go this step (real contact).
///
/// At a no-slip wall node v = 0, and the solid's displacement equation
/// d_t u + v.grad u = v then keeps u, and with it the interface d0(x - u(x)), where it
/// is: a body that touches a wall stays held there for good. That is right for a body at
/// rest on the wall, and it breaks a body that rebounds: the rest of it moves away from
/// the points the wall holds until the solid turns inside out (docs/validation.md, "Real
/// contact at speed"). At a released node the u row is the harmonic extension of the
/// solid's displacement around it instead (forms::ElementInput::u_row_released), so the
/// interface there follows the solid away from the wall; v stays 0 (no slip).
///
/// A node is released when the body as a whole moves away from every wall it lies on
/// faster than kReleaseSpeed_mps (its mean velocity at the step's start). Released
/// always, Example 1 at rest on the ground sank: centroid 3.8 mm lower after 0.3 s and
/// 2.4 cm/s downwards, against 0.0017 m/s held.
#include <vector>

#include <Eigen/Core>

#include "fsi/field_view.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// The speed away from a wall [m/s] above which a body lets go of it: the rebounds of
/// assets/scenarios/impacts/ leave at 0.23-0.5 m/s; the demo's ball, landing the second
/// time, rocks on the ground at up to 0.033 m/s, and released at 0.01 m/s it broke there
/// (t = 4.69 s, 4 steps unconverged before).
inline constexpr double kReleaseSpeed_mps = 0.1;

/// released[n] = 1 for the wall nodes n that touch the solid (touches_solid) and lie only
/// on walls the body (mean velocity `body_velocity_mps`, centroid `centroid_m`) moves
/// away from faster than kReleaseSpeed_mps, the wall's normal taken towards the centroid.
/// Empty when no node is released.
std::vector<char> released_wall_nodes(const mesh::PatchMesh& mesh, const std::vector<Segment2>& walls,
                                      const std::vector<char>& touches_solid,
                                      const Eigen::Vector2d& body_velocity_mps, const Eigen::Vector2d& centroid_m);

}  // namespace fsi::core
