#pragma once
/// \file corner_barrier.hpp
/// The push of the convex wall corners (tread edges) on a body (ours).
///
/// A body that touches a convex corner holds on to it at one no-slip node: v = 0 there, and
/// u, hence the material point, stays. Around a single held node in patches of a few
/// millimetres the solid's displacement changes by the body's motion since the touch within
/// one patch, and after about one patch side of motion det(I - grad u) <= 0. Campaign
/// seed 5 lost five of its forty runs so, landing on a tread's edge at 0.2-0.6 m/s, with
/// and without the contact force (whose corner push, contact_distance.hpp, is scaled for a
/// ball's weight, not for its landing). A flat wall holds the body along a line and stops
/// it; a corner only pins it.
///
/// So a convex corner within `reach_m` of a body pushes it, whatever the contact settings:
/// the pressure P = gamma (reach - d) / max(d, f reach) on the interface points within the
/// body's reach of the corner, d the distance to the line through the corner tangent to
/// the body (CornerLine, contact_distance.hpp). For a round body of radius R the work of that
/// pressure from d = reach to d = 0 is 1.84 gamma reach sqrt(2 R reach) (f = 0.1, the
/// integral in CornerBarrier::gamma_for); gamma is chosen so that this is twice the
/// kinetic energy of the body at the design speed, which leaves half for the fluid's
/// share and for an approach that is not along the corner line.
#include <vector>

#include <Eigen/Core>

#include "core/contact_distance.hpp"
#include "fe/cut_mesh.hpp"
#include "fsi/field_view.hpp"
#include "fsi/scenario.hpp"

namespace fsi::core {

/// The convex corners of `walls`: points where two walls meet, with the wedge of wall
/// material on the side away from `body_centroid` (a tread's edge seen from a ball above
/// or beside it; never a box's inner corner, never two collinear walls).
std::vector<Eigen::Vector2d> convex_corners(const std::vector<Segment2>& walls, const Eigen::Vector2d& body_centroid);

class CornerBarrier {
 public:
  /// The corners of convex_corners(walls, body_centroid) within `reach_m` of the body's
  /// `interface`; `window_m` how far from its corner the tangent line reaches (the body's
  /// radius); `gamma` [N/m] the barrier's strength (gamma_for).
  CornerBarrier(const std::vector<Segment2>& walls, const std::vector<fe::InterfaceSegment>& interface,
                const Eigen::Vector2d& body_centroid, double reach_m, double window_m, double gamma,
                double min_dist_fraction);

  /// The barrier's pressure at the interface point x [Pa]: the largest of its corners'.
  double pressure_pa(const Eigen::Vector2d& x) const;

  /// How many corners push this step.
  int num_corners() const { return static_cast<int>(corners_.size()); }

  /// The strength that stores twice the kinetic energy 1/2 m v^2 of a body of `mass_kg_per_m`
  /// at `speed_mps` within `reach_m` of a corner, for a round body of radius `radius_m`
  /// (FsiSystem: the body's own mass rho_s times its shape's area, a constant of the scenario).
  static double gamma_for(double mass_kg_per_m, double speed_mps, double radius_m, double reach_m);

  /// The reach of a body's barrier: `min_reach_m` (ContactSpec::corner_barrier_reach_m),
  /// or, for a body too soft for the pressure gamma_for gives there, the reach at which
  /// gamma equals its shear modulus `mu_pa` (gamma falls as reach^(-3/2)). The same work
  /// spread over a longer approach: a heavy, soft ball (campaign seed 5, case 24:
  /// rho_s/rho_f = 3.5, mu_s = 6.9e4 Pa, at 0.97 m/s beside a tread's edge) had a
  /// barrier 6.7 times its mu_s within 1 cm and Newton stalled 9 mm from the edge; with
  /// the reach of 3.5 cm it lands on the tread beside the edge and runs to t = 3 s with
  /// every step converged.
  static double reach_for(double mass_kg_per_m, double speed_mps, double radius_m, double min_reach_m,
                          double mu_pa);

 private:
  std::vector<CornerLine> corners_;
  double reach_m_;
  double window_m_;
  double gamma_;
  double min_dist_m_;
};

/// The reach of `body`'s barrier in `scenario`: CornerBarrier::reach_for with the body's
/// mass (rho_s times its shape's area, a constant of the scenario) and shear modulus.
double corner_barrier_reach_m(const Scenario& scenario, const BodySpec& body);

}  // namespace fsi::core
