#pragma once
/// \file state.hpp
/// What changes while a simulation runs (MuJoCo's mjData to Scenario's mjModel).
/// Restoring a State and stepping on gives bit-identical results.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fsi {

/// Unknowns per node, node-major: index = kFieldsPerNode * node + field.
enum Field : int { kVx = 0, kVy = 1, kUx = 2, kUy = 3, kP = 4 };
inline constexpr int kFieldsPerNode = 5;

/// The chapter's quantities of interest at one time level.
struct Functionals {
  double min_distance_m = 0.0;   ///< min over the discrete interface of dist to the walls
  double bottom_y_m = 0.0;       ///< lowest point of the interface
  double top_y_m = 0.0;          ///< highest point of the interface
  double left_x_m = 0.0, right_x_m = 0.0;
  double centroid_x_m = 0.0, centroid_y_m = 0.0;  ///< of the discrete solid domain
  double mean_vy_mps = 0.0;      ///< solid-averaged vertical velocity
  double mean_vx_mps = 0.0;      ///< solid-averaged horizontal velocity
  double solid_area_m2 = 0.0;    ///< |S_h|
  double mass_error = 0.0;       ///< j_mass = |pi r^2 rho0 - int_S J rho0| / (pi r^2 rho0)
  /// Fluid area the cavitation floor creates per second [m^2/s]: the integral over the
  /// fluid of the expansion rate it allows where p < p_cav (numerics.cavitation_pressure_pa;
  /// 0 with the floor off). Not the chapter's: a measure of what the floor changes in an
  /// incompressible fluid (compare with the ball's area, pi r^2).
  double cavitation_rate_m2ps = 0.0;
  /// How far the body has turned since t = 0 [rad, counter-clockwise]: the angle of the
  /// least-squares rigid motion of its solid nodes' initial points onto their positions
  /// (core/rereference.hpp), plus the turns re-referencing took out of u.
  double rotation_rad = 0.0;

  /// One body's share (scenes with several bodies, ours).
  struct Body {
    double centroid_x_m = 0.0, centroid_y_m = 0.0;  ///< of the body's discrete solid
    double mean_vx_mps = 0.0, mean_vy_mps = 0.0;    ///< solid-averaged velocity
    double min_distance_m = 0.0;       ///< min over its interface of dist to the walls
    double min_body_distance_m = 0.0;  ///< min over its interface of the distance to the other bodies' interfaces
    double mass_error = 0.0;           ///< j_mass of this body alone
    double rotation_rad = 0.0;         ///< its turn since t = 0 (counter-clockwise)
    double solid_area_m2 = 0.0;
  };
  /// Per body in scene order (body1, body2, ...); empty in a scene with one body. With
  /// several, the fields above are the scene's: min_distance_m the smallest of the
  /// bodies', mass_error the largest, centroid and velocity those of all the solid, and
  /// rotation_rad body1's.
  std::vector<Body> bodies;
};

struct FactorizationOrigin;

struct State {
  double time_s = 0.0;
  long step = 0;
  double time_step_s = 0.0;  ///< k used for the last step (may be halved by policy)
  /// The longest next step [s] that how the last steps went allows (numerics.time_step_max_doublings
  /// > 0 only): twice the last step after a calm one (converged at its first attempt in at
  /// most core::kCalmNewtonIterations), half the last step after a laborious one, the base
  /// step k after any trouble (a halving, an unconverged or flagged step), and k at the start.
  double time_step_limit_s = 0.0;

  /// Unknowns of level m (v, u, p per node, see Field) on the mesh of level m.
  Eigen::VectorXd solution;
  /// Unknowns of level m-1 (needed by the IPS mapping (12.4)).
  Eigen::VectorXd previous_solution;
  /// The discrete interface of the meshes of level m and m-1 (each level's mesh is
  /// built from the displacement of the level before it, so it cannot be recomputed
  /// from this state alone): per node the corner colouring (-1 solid, +1 fluid, 0 on
  /// the interface or not a patch corner), per grid edge the cut parameter in (0, 1)
  /// or -1 where the edge is not cut.
  std::vector<std::int8_t> corner_sign, previous_corner_sign;
  std::vector<double> edge_cut, previous_edge_cut;

  /// The body's reference configuration (ours): the Initial Point Set measures
  /// the initial ball's distance d0 from its centre moved by this offset [m], and the
  /// displacement u of both levels is measured from the ball turned by
  /// reference_rotation_rad [rad, counter-clockwise] and moved so. Zero unless the engine
  /// re-references (numerics.rereference_angle_rad): then u is the elastic part of the
  /// motion, and its harmonic extension into the fluid stays small (core/rereference.hpp).
  double reference_offset_x_m = 0.0, reference_offset_y_m = 0.0;
  double reference_rotation_rad = 0.0;
  /// The same for each body of a scene with several (ours; empty with one body, whose
  /// reference is the three numbers above). Such a scene re-references every body after
  /// every step: u holds one step's motion and the elastic part, so that its extension
  /// through the fluid between two bodies that move apart or together stays small.
  struct BodyReference {
    double offset_x_m = 0.0, offset_y_m = 0.0, rotation_rad = 0.0;
  };
  std::vector<BodyReference> body_references;

  Functionals functionals;

  /// Where the LU factorization that Newton currently reuses was computed (the solver
  /// keeps one factorization across iterations and time steps while it contracts well).
  /// Part of the state so that a restored run rebuilds exactly that factorization and
  /// continues bit-identically. Null before the first step.
  std::shared_ptr<const FactorizationOrigin> factorization_origin;
};

/// The data that determines a factorized Jacobian: the state at the start of the step
/// it belongs to (without an origin of its own), the Newton iterate and the time step.
struct FactorizationOrigin {
  State step_start;
  Eigen::VectorXd iterate;
  double time_step_s = 0.0;
};

}  // namespace fsi
