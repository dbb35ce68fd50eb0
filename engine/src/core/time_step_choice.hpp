#pragma once
/// \file time_step_choice.hpp
/// How long the next step is (ours: the chapter's steps all have the one length k).
///
/// The stairs spend hours on a ball that is in flight most of the time, far from every
/// wall, where nothing needs k = 1e-3 s: 40 ms of flight at k, 2k, 4k and 8k end at the
/// same place to 0.2 mm and the same speed to 1e-4 m/s, for 1, 0.55, 0.28 and 0.15 of the
/// CPU time (docs/method.md, "Time-step length"). Near a wall the step
/// stays k: there the cut passes the thin rows and the contact force acts, and the runs
/// failed at 2k.
///
/// With numerics.time_step_max_doublings = n > 0 (time_step_max_s() = k 2^n) the next step
/// is k 2^j for the largest j with
///   j <= n,
///   kStepsToWallZone * |v| * k 2^j <= min_distance - time_step_wall_zone_m,
///   |v| * k 2^j <= time_step_patch_fraction * h_cut
/// (v the body's mean velocity, min_distance its interface's distance to the walls, h_cut
/// the shortest side of the patches its interface cuts), and not past end_time_s. The
/// second condition makes a body approaching a wall come down to k step by step, at
/// least kStepsToWallZone steps before it enters the zone; a body inside the zone takes k,
/// or with numerics.time_step_wall_zone_doublings = m > 0 steps up to k 2^m as long as
///   kStepsToWallZone * |v| * k 2^j <= min_distance and
///   |v| * k 2^j <= kWallZonePatchFraction * time_step_patch_fraction * h_cut
/// (a ball resting on a wall, not one rolling on it), where |v| is here the larger of the
/// mean speed and what the solid's nodes reach within kWallZoneLookahead_s at their
/// present speed and acceleration (SolidMotion); in real contact (min_distance 0) by the
/// patch condition alone (a body at rest there; touching a wall node, at most
/// kTouchingStepFactor k), without an interface always k. The third keeps the interface
/// from crossing more of a patch per step than k does in the thin rows: the graded rows
/// above the treads reach 10 cm up, and there 8e-3 s steps (3.5 mm in 21 mm rows) failed
/// where the cut moved past nodes (rho_f = 100 at t = 6.2 s). Besides, the
/// step grows by at most 2 per step and only while Newton converges easily, halves when
/// Newton labours, and any trouble sends it back to k (next_time_step_limit): with the
/// geometric conditions alone 4e-3 s steps still failed there, after a
/// halved step had been followed by a 4e-3 s one.
#include "fe/cut_mesh.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// A long step may cover at most this fraction (its inverse) of the way to the wall zone.
inline constexpr double kStepsToWallZone = 4.0;

/// In the wall zone a longer step may move the interface by only this part of what
/// time_step_patch_fraction allows elsewhere. A ball rolling on tread 1 at 0.19 m/s in
/// steps of 4e-3 s (0.77 mm, 1/8 of the 6 mm rows it cut) met cut changes that k takes in
/// its stride with residuals of 1e4 at their start and three unconverged steps; at k it
/// moves 0.19 mm (1/32). A ball at rest on the floor (|v| < 0.017 m/s) still takes 8e-3 s
/// steps: 69 instead of 500 for 0.5 s, the same motion (docs/method.md, "Time-step length").
inline constexpr double kWallZonePatchFraction = 0.25;

/// In the wall zone a body counts as slow only if its solid nodes stay slow for this long
/// [s] at their present acceleration: at the turn of an impact the mean velocity passes
/// through zero (the stiff contact-study ball decelerates at about 8 m/s^2), and a rule
/// on the speed alone took 1e-3 and 2e-3 s steps there, in which the squeeze film drains
/// faster (its CIP leak grows with k) and the ball's rims were pulled onto the ground
/// (docs/method.md, "Time-step length"). At the turn the look-ahead adds 0.16 m/s or more, enough
/// to keep k = 5e-4 s in the ground's 3 mm rows; a ball settling in the film (1 cm/s,
/// about 0.05 m/s^2) gains 1 mm/s and keeps its longer steps (with 0.05 s the
/// integration test's sinking ball lost them).
inline constexpr double kWallZoneLookahead_s = 0.02;

/// An interface through a wall node measures 1e-17 to 5e-17 m from the wall (the rounding
/// of the node's coordinates): a distance below this [m] is a touch, real contact.
inline constexpr double kTouchingDistance_m = 1e-12;

/// Steps of a body at rest touching a wall are at most this many times k (the wall zone allows 4). From Example 1's
/// state at rest on the ground at t = 4.676 s to 5.5 s: with k 389 steps and 421 Newton
/// iterations; with 2k 206 steps and 292 iterations, the centroid within 4.7e-5 m of the run
/// with k (it settles by 4.5e-4 m meanwhile); with 4k 119 steps and 282 iterations, but
/// 4.5e-4 m off, as much as the settling itself. Every step of the three converged.
inline constexpr double kTouchingStepFactor = 2.0;

/// A step that converged at its first attempt in at most this many Newton iterations lets
/// the next one be twice as long. Calm flight takes 4-7 at 8e-3 s (and 3-5 at k); the
/// rho_f = 100 stairs failure at t = 6.2 s was preceded by steps of 8-13 and by unconverged
/// ones, each followed by another long step.
inline constexpr int kCalmNewtonIterations = 7;

/// How fast the solid moves and how fast that changes, from the nodes: the wall-zone rule's
/// look at a body that is slow on average but not at rest.
struct SolidMotion {
  double max_speed_mps = 0.0;  ///< the largest |v| at a node of a solid sub-element
  /// The largest |v^m - v^{m-1}| / k at the nodes inside the solid at both levels.
  double max_acceleration_mps2 = 0.0;
};

/// SolidMotion of `solution` on `cut` against `previous_solution` on `previous_cut`, the
/// step between them last_step_s [s] long (0: no acceleration). The acceleration only at
/// nodes that belong to solid sub-elements alone at both levels: at the interface a node
/// changes its place or its phase between the levels, and its difference is no
/// acceleration. The Eulerian difference at a fixed node also carries v.grad v, which is
/// small for the near-rigid motion this is asked about.
SolidMotion solid_motion(const fe::CutMesh& cut, const Eigen::VectorXd& solution, const fe::CutMesh& previous_cut,
                         const Eigen::VectorXd& previous_solution, double last_step_s);

/// The next step's length [s] for a body with the given functionals at time_s [s] whose
/// interface cuts patches with sides down to cut_patch_side_m [m], at most
/// history_limit_s (State::time_step_limit_s; 0: none, as the tests of the geometric
/// conditions alone use).
/// `motion` (default: none, the mean velocity alone) for the wall-zone rule.
double choose_time_step(const NumericsSpec& numerics, const Functionals& functionals, double cut_patch_side_m,
                        double time_s, double history_limit_s = 0.0, const SolidMotion& motion = {});

/// How the step just accepted went, for the next step's limit.
struct StepOutcome {
  double time_step_s = 0.0;    ///< the accepted step's length [s]
  bool calm = false;           ///< converged at its first attempt
  int newton_iterations = 0;   ///< of that attempt
};

/// State::time_step_limit_s after `outcome` (base_step_s: numerics.time_step_s): the step
/// grows by at most a factor 2 per step and only after calm steps, is halved after a
/// laborious one (more iterations), and falls back to the base step after any trouble
/// (the standard controller of implicit integrators with Newton: the iteration count is
/// the cheapest warning that a step is too long).
double next_time_step_limit(const StepOutcome& outcome, double base_step_s);

/// The shortest side (PatchMesh::Patch::min_size_m) of the patches the interface of
/// `cut` cuts or touches; infinity without an interface.
double cut_patch_side(const mesh::PatchMesh& mesh, const fe::CutMesh& cut);

}  // namespace fsi::core
