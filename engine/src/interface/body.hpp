#pragma once
/// \file body.hpp
/// The body's initial geometry d0 (signed distance, negative inside) and the Initial
/// Point Set level set phi(x) = d0(x - u(x)) (docs/method.md, "The interface").
#include <span>
#include <vector>

#include "fe/point_locator.hpp"
#include "fsi/scenario.hpp"

namespace fsi::interface {

using mesh::Vec2;

/// Signed distance [m] to the ellipse or rounded rectangle of `body` (BodySpec::shape),
/// exact: the ellipse's by the bisection of D. Eberly, "Distance from a Point to an
/// Ellipse" (robust to the points on its axes), the rounded rectangle's in closed form.
double shape_distance(const BodySpec& body, const Vec2& X);

/// The initial signed distance d0(X) [m], negative inside: |X - c| - r for the ball.
inline double initial_distance(const BodySpec& body, const Vec2& X) {
  if (body.shape != BodyShape::circle) return shape_distance(body, X);
  return (X - Vec2(body.center_m.x, body.center_m.y)).norm() - body.radius_m;
}

/// The fluid's velocity [m/s] at x (outside the ball) at t = 0 when the ball starts with
/// body.initial_velocity_mps = U: the potential flow of a circle moving at U through
/// fluid at rest far away, v = (R/r)^2 (2 (U.e_r) e_r - U), r = |x - c| (divergence-free,
/// its normal component U.e_r at the interface, decaying like 1/r^2): the flow an
/// impulsive start sets up at once. Started in fluid at rest instead, the first step
/// gives the fluid its share of the momentum (a ball of the fluid's density thrown at
/// 1 m/s across a U-shaped box moved at 0.45 m/s three steps later, against 0.79 m/s
/// from this flow) and the steps after it did not converge (ThrownBall.*). Zero for U = 0.
/// Other shapes take the flow of the circle of their area: a start the first step
/// corrects, as it corrects the circle's flow for the walls.
Vec2 initial_fluid_velocity(const BodySpec& body, const Vec2& x);

/// The scene's d0: the smallest of the bodies' d0 (negative inside any body). Bodies are
/// disjoint, so inside a body it is that body's d0 and between bodies the distance to the
/// nearest one.
double scene_distance(std::span<const BodySpec> bodies, const Vec2& X);

/// Index of the body whose d0 is smallest at X (the body X belongs to, or the nearest).
/// Where two bodies share the smallest d0: the lower index, or, if `ties` is negative,
/// `ties` for every point whose two smallest d0 are within kTieDistance_m (a point on the
/// mirror line between two bodies belongs to neither, whatever the rounding of its u).
int nearest_body(std::span<const BodySpec> bodies, const Vec2& X, int ties = 0);

/// Two d0 this close [m] are equal for nearest_body's ties: rounding of u and d0 at the
/// size of a lab set-up is 1e-16 m.
inline constexpr double kTieDistance_m = 1e-12;

/// The initial flow of several bodies: the sum of each body's potential flow (exact for
/// one body; for several a start that the first step corrects, like the walls).
Vec2 initial_fluid_velocity(std::span<const BodySpec> bodies, const Vec2& x);

/// phi(x) = d0(x - u(x)) for the displacement coefficients `solution` on `cut`, d0 the
/// scene's (scene_distance). Points the locator cannot place (outside the domain) use
/// u = 0. `bodies` must outlive the returned function.
fe::LevelSet ips_level_set(std::span<const BodySpec> bodies, const fe::CutMesh& cut,
                           const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution);
inline fe::LevelSet ips_level_set(const BodySpec& body, const fe::CutMesh& cut, const fe::PatchBuckets& buckets,
                                  const Eigen::VectorXd& solution) {
  return ips_level_set(std::span<const BodySpec>(&body, 1), cut, buckets, solution);
}

/// The body each sub-element of `next` belongs to: nearest_body at its reference point
/// x_c - u(x_c), x_c its centroid, u the displacement `solution` on `cut` (the mesh whose
/// ips_level_set `next` was cut by). -1 for fluid sub-elements; with one body, 0 for
/// every solid one.
std::vector<int> element_bodies(std::span<const BodySpec> bodies, const fe::CutMesh& next, const fe::CutMesh& cut,
                                const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution);

/// The body of each interface segment of `cut`: that of its patch's solid sub-elements
/// (element_body: element_bodies of `cut`; empty or of another size: body 0 everywhere).
std::vector<int> segment_bodies(const fe::CutMesh& cut, const std::vector<int>& element_body);

}  // namespace fsi::interface
