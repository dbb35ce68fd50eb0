#pragma once
/// \file scenario.hpp
/// Everything that defines a simulation and does not change while it runs: geometry,
/// mesh, materials, body, numerics, outputs. Defaults are the member initialisers: the
/// chapter's Example 1 (falling ball) on the 4225-node mesh, with the fsi numerics
/// (Method::fsi; numerics_for(Method::chapter) gives the chapter's numerics).
///
/// A Scenario is validated once where it is built (load_scenario / validate); all code
/// after that relies on it. Units are SI and carried in the member names.
#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fsi/field_view.hpp"

namespace fsi {

/// One graded piece of a mesh axis: `patches` patches between coordinates `from` and
/// `to`, the first patch (at `from`) of size `first`, the last (at `to`) of size `last`.
/// Positions follow x(t) = from + L (c t + (1 - c) t^q), t = i/patches, with c and q
/// chosen so the end sizes match (q = 1: uniform; q = 2: linearly growing sizes).
/// `from` may be larger than `to` (a piece graded away from its start leftwards).
struct AxisPiece {
  double from_m = 0.0;   ///< coordinate where the piece starts [m]
  double to_m = 1.0;     ///< coordinate where the piece ends [m]
  int patches = 1;       ///< number of patches between from_m and to_m
  double first_m = 1.0;  ///< size of the patch at `from` [m] (0: uniform)
  double last_m = 1.0;   ///< size of the patch at `to` [m] (0: uniform)
};

/// One structured block of patches. Without `corners` the block is the axis-aligned
/// rectangle spanned by the axes. With `corners` (counter-clockwise, starting at the
/// lower-left), the axes live in the unit square [0,1]^2 and are mapped bilinearly;
/// that is how the stairs' inclined plane is meshed. Blocks must meet node to node.
struct BlockSpec {
  std::vector<AxisPiece> x;  ///< patch lines in the first direction
  std::vector<AxisPiece> y;  ///< patch lines in the second direction
  bool mapped = false;   ///< true: the block is the quadrilateral `corners`, mapped bilinearly
  std::array<Point2, 4> corners{};  ///< mapped: corners counter-clockwise from lower-left [m]
  /// Mapped blocks only: the patch lines along the right side (s = 1), in unit-square
  /// coordinates like `y` (which then gives those along the left side, s = 0), with the
  /// same number of patches. Each line of patches runs straight from its node on the left
  /// side to its node on the right side (transfinite interpolation between the two
  /// sides), so a block can carry the thin rows above a tread on its left over into coarse
  /// rows on its right and still meet both neighbours node to node: the stairs' fan
  /// blocks beside each riser. Empty: the same as `y`.
  std::vector<AxisPiece> y_right;
};

struct MeshSpec {
  std::vector<BlockSpec> blocks;  ///< at least one
  int refinements = 0;            ///< global refinements (each patch -> 2x2), 0..4
};

/// St. Venant-Kirchhoff solid (12.2).
struct SolidSpec {
  double density_kgpm3 = 1000.0;  ///< reference density rho_s^0
  double mu_pa = 2.0e5;           ///< shear modulus mu_s [Pa]
  double lambda_pa = 8.0e5;       ///< first Lame parameter lambda_s [Pa]
};

/// The body's shape at t = 0, given by its signed distance d0 (negative inside).
enum class BodyShape {
  circle,            ///< d0 = |x - c| - radius_m (the chapter's ball)
  ellipse,           ///< semi-axes half_size_m, turned by angle_rad
  rounded_rectangle  ///< half width and height half_size_m, corners of radius radius_m, turned by angle_rad
};

/// An elastic body.
struct BodySpec {
  Point2 center_m{0.0, 0.0};              ///< centre of the body at t = 0 [m]
  /// circle | ellipse | rounded_rectangle (ours, except the circle). Give an ellipse or a
  /// rounded rectangle a side of at least two patches and corners of at least a patch:
  /// a patch holds one straight cut.
  BodyShape shape = BodyShape::circle;
  double radius_m = 0.4;                  ///< circle: radius; rounded_rectangle: corner radius [m]
  /// ellipse: semi-axes; rounded_rectangle: half width and half height [m] (along the
  /// body's own axes, which angle_rad turns); not used by the circle.
  Point2 half_size_m{0.4, 0.4};
  double angle_rad = 0.0;                 ///< counter-clockwise turn of the body's own x axis at t = 0
  Point2 initial_velocity_mps{0.0, 0.0};  ///< velocity of the whole body at t = 0 [m/s]
  /// The body's own material (ours); none: the scenario's `solid`.
  std::optional<SolidSpec> solid;
};

/// The body's area at t = 0 [m^2]: pi r^2, pi a b, 4 a b - (4 - pi) r^2 (what the mass
/// error compares with).
double body_area(const BodySpec& body);

/// The largest distance [m] from the centre to a point of the body (the ball's radius).
double body_reach(const BodySpec& body);

struct FluidSpec {
  double density_kgpm3 = 1000.0;   ///< rho_f
  double viscosity_m2ps = 1.0e-3;  ///< kinematic nu_f
};


/// What to do with a step whose Newton iteration did not converge within the budget.
/// Whatever the policy, an attempt in which Newton never moved its iterate (no line
/// search succeeded) is not kept: the step is rejected rather than advanced with the body
/// frozen where it was.
enum class FailurePolicy {
  accept_and_flag,   ///< keep the result, report converged = false
  halve_step,        ///< retry with k/2 (up to max_halvings), then accept and flag the best
  stop_and_rollback  ///< restore the state before the step and report failure
};

/// Which numerics a scenario starts from (top-level key "method"); keys a file gives win.
enum class Method {
  /// The configuration that works (the default): the chapter's discretization with our
  /// additions on (longer steps away from the walls, error control, the cavitation floor,
  /// backflow stabilization, re-referencing) and looser Newton tolerances. Measured
  /// (docs/validation.md, "Performance"): Example 1 with these steps, error control,
  /// tolerances and floor reached 5 s in 1528 steps, the chapter's numerics with the floor
  /// stopped at 4.898 s in real contact; backflow stabilization and re-referencing were
  /// not on in those runs.
  fsi,
  /// The chapter's method unchanged, every addition of ours off: for validation against
  /// the chapter (Table 12.1).
  chapter
};

/// The numerics. The member initialisers are the fsi preset (Method::fsi); numerics_for()
/// gives the chapter's (Method::chapter), which differs only in the members listed there.
/// Members marked "advanced" are solver knobs a scenario rarely needs to set.
struct NumericsSpec {
  double time_step_s = 2.0e-3;  ///< k [s], the base step (typical 5e-4 .. 2e-3)
  /// Longer steps away from the walls (advanced; ours; 0 = off, the chapter: every step
  /// is k). A body outside the wall zone takes steps k 2^j up to k 2^n, n this number
  /// (range 0..6), as long as at its speed it needs at least four of them to reach the
  /// zone (core/time_step_choice.hpp), starting at k and at most doubling after each step
  /// Newton solved easily, back to k after any trouble (State::time_step_limit_s). A solver
  /// control: which length the next step has does not change what a state is. Relative to
  /// k, so a scenario with a finer k keeps the same ratio.
  int time_step_max_doublings = 3;
  /// The wall zone [m] (advanced): a body whose interface is closer than this to a wall (or,
  /// with several bodies, to another body) takes steps of time_step_s. With the contact force
  /// on, the zone is at least contact.dist0_m: longer steps inside the force's reach could
  /// carry a body deep into it in one step (the force is explicit in a step).
  double time_step_wall_zone_m = 0.03;
  /// ... (advanced) and while its speed times the step stays within this fraction of the shortest side
  /// of the patches its interface cuts (k itself moves it by up to 1/8 of the stairs' 4 mm
  /// rows at 0.5 m/s).
  double time_step_patch_fraction = 0.125;
  /// Inside the wall zone (advanced; ours; 0 = off, every step there is time_step_s).
  /// A body in the zone may take steps k 2^j up to k 2^n, n this number (a larger number
  /// than time_step_max_doublings acts as that one), while at its speed it needs at least four of them to reach
  /// the wall itself (in real contact: no such condition, a body at rest there) and moves
  /// by at most a quarter of what time_step_patch_fraction allows elsewhere, the speed
  /// being the larger of the mean and what its solid nodes reach within 0.02 s at their
  /// present acceleration (a ball at the turn of an impact takes k); the step-length
  /// controller still bounds it. For a ball at rest on a wall (a ball rolling on it at
  /// 0.2 m/s still takes k: core/time_step_choice.hpp).
  int time_step_wall_zone_doublings = 2;
  /// The longest step away from the walls [s]: k 2^time_step_max_doublings, 0 when off.
  double time_step_max_s() const {
    return time_step_max_doublings > 0 ? time_step_s * (1 << time_step_max_doublings) : 0.0;
  }
  /// The longest step inside the wall zone [s]: k 2^n, n = min(time_step_wall_zone_doublings,
  /// time_step_max_doublings), 0 when n = 0 (off).
  double time_step_wall_zone_max_s() const {
    const int n = time_step_wall_zone_doublings < time_step_max_doublings ? time_step_wall_zone_doublings
                                                                          : time_step_max_doublings;
    return n > 0 ? time_step_s * (1 << n) : 0.0;
  }
  /// Error control (advanced; ours; 0 = off): the largest estimated local error of a step in the
  /// body's position [m] (core/time_error_estimate.hpp). After each step the next one may
  /// be at most k (tolerance / error)^{1/2} x 0.8 long (between a quarter and twice the
  /// step just taken), on the ladder time_step_s 2^j, j >= -3, within the other limits
  /// above. A dG(0) step of 2e-3 s in Example 1's fall (0.2 m/s^2) errs by about 4e-7 m.
  double time_error_tolerance_m = 1.0e-5;
  double end_time_s = 5.0;  ///< simulated time at which a run (fsi-movie) ends [s]
  int newton_budget = 12;            ///< max Newton iterations per step (advanced; bounded cost)
  double newton_rel_tol = 1.0e-6;    ///< stop when |R| <= rel_tol |R_0| ... (advanced)
  double newton_abs_tol = 1.0e-10;   ///< ... or |R| <= abs_tol (scaled residual; advanced)
  /// Reuse the factorization while each iteration reduces the residual by this factor (advanced).
  double reuse_contraction = 0.5;
  /// Where Newton needs the Jacobian at a new iterate: solve it by GMRES preconditioned
  /// with the factorization held, up to this many GMRES iterations, and refactorize only
  /// when that does not converge (advanced; ours; 0: refactorize every time). A
  /// factorization of the stairs' 71k unknowns costs about 80 solves with one.
  int krylov_iterations = 0;
  /// Threads of the element loops and the factorization (advanced; residual and Jacobian
  /// assembly, old values at T_m, the LU's two blocks at the same time); 0: the machine's
  /// hardware threads, at most 8. A solver control: the results are bit-identical for
  /// every thread count (patches are assembled in groups that share no node; each old
  /// value is computed on its own; the two blocks are independent LUs).
  int assembly_threads = 0;
  /// What to do with a step Newton did not solve within its budget, or whose solution
  /// broke the body (advanced; FailurePolicy; the chapter's method: accept_and_flag).
  /// Halving is the default because a step accepted unconverged near a wall is where
  /// bodies broke: at Example 1's film formation (t = 2.334 s), before the chord-step rule
  /// of solve/newton.cpp, a step accepted unconverged at 2e-3 s broke the body one step
  /// later; halved, it converged at 5e-4 s.
  FailurePolicy failure_policy = FailurePolicy::halve_step;
  int max_halvings = 3;  ///< halve_step: how many times a step may be halved (advanced)
  /// halve_step only (advanced; ours): an attempt that did not converge but brought its scaled
  /// residual down to this fraction of its start or below is accepted and flagged at once,
  /// without the retries at k/2, k/4, ... (0: retry every failure). Where Newton stalls just
  /// short of the tolerance (the stairs' thin rows at a corner: 1e-5 of the start), the
  /// smaller steps stall alike and only multiply the cost; a step that really failed
  /// (a reduction of 0.3, say) is still retried.
  double accept_flagged_reduction = 0.0;
  /// ... and only if its final scaled residual is at or below this (advanced; ours).
  /// A step whose start was far off (real contact at a corner: 74 or 1e7) gets down by 1e-5
  /// of it and still ends at 8e-4 or 6e-2, no solution: accepted, such steps broke the body
  /// within three steps, while halved they converged. Stalls near the tolerance (1e-7 ..
  /// 1e-4) are still accepted at once.
  double accept_flagged_max_residual = 1.0e-4;
  /// With halve_step (advanced; ours; 0 = no bound): the best of a step's attempts is accepted when
  /// every halving failed only if its final scaled residual is at most this; above it the
  /// step is rejected and the state rolled back, so a run stops with a report instead of
  /// going on from a state that solves nothing. A rho_f = 100 stairs run that accepted
  /// bests of 21 and 1.4e4 blew its body up two steps later (mass error 4), yet the same
  /// run had gone on well after a best of 2150, hence no default bound.
  double accept_best_max_residual = 0.0;
  /// Re-reference the body when its rigid rotation since the last reference exceeds this
  /// [rad] (advanced; ours; 0 = never, the chapter; typical 0.05): u is then measured from the ball
  /// turned and moved with the body, which changes no stress, density or interface, but
  /// keeps u and its harmonic extension into the fluid small. Without it a ball that has
  /// rolled carries u = (I - Q) x + ..., whose extension must bend to zero normal
  /// derivative at every wall within the gap: near a wall the IPS level set and Newton's
  /// start for newly covered nodes go wrong (core/rereference.hpp). Part of the
  /// discretization (the extension, hence the cut, changes), so in the fingerprint. A scene
  /// of several bodies re-references every body after every step whatever this says
  /// (docs/method.md, "Several bodies").
  double rereference_angle_rad = 0.05;

  double cip_gamma = 0.05;        ///< gamma of S_aniso (advanced; scaled by 1/(rho_f nu_f))
  /// Weight w of the transient term in the CIP scaling gamma h^2 / (rho_f nu_f + w rho_f h^2 / k)
  /// (advanced; ours): 1 scales like PSPG's tau ~ k / rho, 0 is the chapter's Stokes scaling.
  double cip_transient_weight = 1.0;
  /// Film factor kappa (advanced; ours; 0 = off, the chapter): a fluid sub-element of a cut patch
  /// with a node on a no-slip wall uses h = min(h_P, kappa h_K) instead of h_P in the CIP
  /// scaling, h_K its smallest height. In a thin wall film the h_P-scaled term lets the
  /// fluid leak along the film faster than lubrication flow (h_K^3 / (12 mu) grad p)
  /// could drain it; with kappa ~ 1 the leak scales like h_K^3 too.
  double cip_wall_film_factor = 0.0;
  double solid_alpha = 0.1;       ///< alpha of the solid velocity stabilization (12.7; advanced)
  double solid_s = 2.0;           ///< exponent s in alpha h^s (advanced)
  double blend_eps_patches = 1.5; ///< eps of the T_m blend g, in patch sizes (advanced)
  double blend_delta_patches = 3.0;  ///< delta of the T_m blend g, in patch sizes (advanced)
  /// A cut closer than cut_snap x (patch side) to a patch corner goes through the corner
  /// (advanced; ours). A cut just beside a corner leaves a sub-element a fraction of a millimetre
  /// wide whose nodal values are nearly free, and Newton stalls on it (the stairs' thin
  /// rows; docs/solver.md, "Cut snapping and thin rows"). Snapping moves the interface by at most cut_snap x side.
  double cut_snap = 1.0e-6;
  /// A cut closer than this distance [m] to a patch corner goes through the corner too
  /// (advanced; ours; 0 = off, the default). cut_snap is relative to the side it lies on, which in
  /// flat patches (the stairs' 4-8 mm rows, 5.6 cm wide) is either too small for the short
  /// sides or moves the interface by millimetres along the long ones; a distance treats
  /// both alike. Range [0, 0.1] m.
  double cut_snap_distance_m = 0.0;
  /// Flat patches (a side 8 or more times the other, like the 3.1 mm x 2.5-10 cm rows at a
  /// wall): a cut on a long side moves to the side's end or midpoint when the interface
  /// passes within cut_align_fraction x (short side) of it (twice that on a wall), and a
  /// patch whose fan of sub-triangles has an angle above 150 degrees moves its centre
  /// across from a cut (advanced; ours; 0 = off, the chapter; the default 0.1). Cuts
  /// anywhere else on a long side leave sub-elements with angles of up to 175 degrees, and
  /// a body touching a wall there stops converging (docs/solver.md, "Cut snapping and thin
  /// rows"). Range [0, 0.5].
  double cut_align_fraction = 0.1;
  /// T_m = id where the body is closer than this to a wall (the chapter's contact gap; advanced).
  double identity_gap_m = 0.0;    ///< 0: one patch height at the wall
  /// Cavitation floor p_cav [Pa] (ours; 0 = off, the chapter; the default -1e4). Where the fluid pressure
  /// falls below p_cav the divergence equation lets the fluid expand,
  /// div v = max(0, p_cav - p) / (rho_f nu_f) (rounded C^1 over |p_cav|/4), so the
  /// pressure cannot fall far below p_cav. Without it the film under a rebounding ball
  /// sucks the ball back with arbitrarily large tension and the ball never lifts off
  /// (docs/method.md, "Cavitation floor"). Range [-1e9, 0].
  double cavitation_pressure_pa = -1.0e4;
  /// Backflow stabilization beta (advanced; ours; 0 = off, the chapter's plain do-nothing; the default 1). Where
  /// fluid enters through an open boundary (v.n < 0) the natural condition becomes
  /// sigma_red n = beta rho_f / 2 (v.n)_- v (Braack & Mucha's directional do-nothing):
  /// with beta = 1 it takes out exactly the kinetic energy the inflow carries in, which
  /// plain do-nothing lets grow without bound (the resting ball's wake fed through the
  /// top grew e-fold in about 0.6 s; docs/method.md, "Backflow stabilization"). Outflow
  /// (v.n >= 0) is unchanged. Range [0, 1].
  double backflow_beta = 1.0;
};

/// The numerics of a preset: Method::fsi gives the member initialisers of NumericsSpec,
/// Method::chapter the chapter's method (every addition of ours off, Newton as in the
/// chapter's Table 12.1 runs). The one place where the two presets differ.
NumericsSpec numerics_for(Method method);

/// Keys renamed in the scenario format; files with the old key still load (the reader
/// converts time_step_max_s to doublings = floor(log2(max / time_step_s)), 0 for 0).
struct RenamedKey {
  const char* old_key;  ///< under /numerics
  const char* new_key;  ///< under /numerics
};
inline constexpr RenamedKey kRenamedNumericsKeys[] = {
    {"time_step_max_s", "time_step_max_doublings"},
    {"time_step_wall_zone_max_s", "time_step_wall_zone_doublings"}};

/// Penalty contact (Sect. 12.5): P_c = gamma_c (dist_0 - dist)/dist for dist < dist_0.
struct ContactSpec {
  double gamma_c = 0.0;  ///< [N/m] (0 disables contact)
  double dist0_m = 0.0;  ///< reference distance dist_0 [m]
  /// P_c is evaluated with dist >= min_dist_fraction * dist_0 (ours; the chapter is
  /// silent). The formula is infinite where the body really touches (dist = 0). Bounded,
  /// it stays below 10 gamma_c for the default 0.1 and is unchanged at every rest
  /// distance the chapter reports (dist >= 0.18 dist_0), and a contact the force could
  /// not prevent no longer throws the body off with an arbitrarily large impulse.
  double min_dist_fraction = 0.1;
  /// A wall end point (a tread's edge) within dist_0 of the body pushes like a flat wall
  /// through it, tangent to the body (ours). The chapter's dist to the
  /// point itself lets a corner push with about a tenth of a flat wall's force at a 2 mm
  /// gap, too little to keep a ball rolling over the edge off it (docs/method.md, "Corners
  /// push like walls"). false: the chapter's formula literally.
  bool corners_as_walls = true;
  /// A convex wall corner (a tread's edge) pushes a body that comes within
  /// corner_barrier_reach_m of it, with or without the contact force (ours): a body that
  /// touches a corner sticks to its one no-slip node and is torn apart within a few
  /// steps, at any speed (docs/method.md, "Corner barrier"). The barrier is P_c with
  /// dist to the corner's tangent line and a gamma of its own, per body, so strong that
  /// it stores twice the kinetic energy of the body at this speed [m/s] before the
  /// body reaches the corner; 0 switches the barrier off. Typical: 1 (the campaign's
  /// envelope), advanced.
  double corner_barrier_speed_mps = 1.0;
  /// How far from a convex corner its barrier reaches at least [m] (advanced; typical 1e-2,
  /// a few wall-patch heights). A body too soft for the barrier's pressure there gets a
  /// longer reach, where the barrier's strength is its shear modulus mu_s (the same work
  /// over a longer approach).
  double corner_barrier_reach_m = 1.0e-2;
};

struct OutputSpec {
  /// A frame every frame_every x numerics.time_step_s of simulated time (every n-th step
  /// while every step is time_step_s long).
  int frame_every = 10;
  int width_px = 1280;   ///< frame width [pixels]
  int height_px = 720;   ///< frame height [pixels]
  int fps = 30;          ///< frames per second of the movie
  std::string field = "vy";    ///< vx | vy | vmag | p | umag
  bool mesh_overlay = false;  ///< draw the cut mesh over the field
  double range_min = 0.0;      ///< fixed colour range (min == max: automatic)
  double range_max = 0.0;     ///< upper end of the fixed colour range
};

struct Scenario {
  /// The preset the numerics start from ("fsi" or "chapter"); the file's numerics keys
  /// override it. Read first, whatever its place in the file.
  Method method = Method::fsi;
  std::string name = "ball_drop";  ///< names the run (and its files)
  std::filesystem::path source = "<defaults>";  ///< file it came from (for messages)
  MeshSpec mesh;
  /// No-slip walls. A domain boundary edge lying on a wall gets v = 0; every other
  /// boundary edge is open (do-nothing). Walls also drive contact and distances.
  std::vector<Segment2> walls;
  /// The body of a scene with one body (the chapter's). Ignored when `bodies` is not empty.
  BodySpec body;
  /// Several bodies (ours; at most 8), named body1, body2, ... in this order in the
  /// functionals and reports. Empty: the one `body`. Bodies must not overlap at t = 0.
  std::vector<BodySpec> bodies;
  FluidSpec fluid;
  SolidSpec solid;  ///< the material of every body that does not give its own
  Point2 gravity_mps2{0.0, -0.5};  ///< acts on the solid only (docs/method.md, "Gravity")
  /// Gravity on the density difference: the solid feels (rho_s - rho_f) g, the fluid none
  /// (its weight is in the reduced pressure), so a body lighter than the fluid rises and
  /// one of the fluid's density floats. false (the chapter's model): the solid feels
  /// rho_s g, as if the fluid were weightless (docs/method.md, "Gravity").
  bool buoyancy = false;
  NumericsSpec numerics;
  ContactSpec contact;
  OutputSpec output;
};

/// The scene's bodies: `bodies`, or the one `body` when that list is empty.
std::span<const BodySpec> scene_bodies(const Scenario& scenario);

/// The material of `body` in `scenario`: its own, or the scenario's `solid`.
const SolidSpec& body_solid(const Scenario& scenario, const BodySpec& body);

/// The chapter's Example 1 (falling ball) on the coarse 4225-node mesh, k = 2e-3 s, with
/// the numerics of `method` (the default: fsi; Method::chapter: the chapter's Example 1
/// exactly).
Scenario example1_scenario(Method method = Method::fsi);

/// Checks every field; throws fsi::InputError naming scenario.source, the key and the
/// allowed range.
void validate(const Scenario& scenario);

/// Reads and validates a JSON scenario file. Throws fsi::InputError.
/// The file overrides Example 1: keys it leaves out keep example1_scenario(method)'s values,
/// method the file's "method" (`{}` is Example 1 with the fsi numerics); unknown or duplicate keys are errors. JSON keys equal the member
/// names; points are [x, y], walls [[x0, y0], [x1, y1]], enums their names. See
/// assets/scenarios/README.md.
Scenario load_scenario(const std::filesystem::path& file);
/// Same, from a string (`origin` is used in error messages).
Scenario parse_scenario(const std::string& json_text, const std::string& origin);
/// The scenario as JSON (round-trips through parse_scenario).
std::string to_json(const Scenario& scenario);
/// A stable fingerprint of the scenario's physics and numerics (for checkpoints): 16 hex
/// digits of a 64-bit FNV-1a hash of the canonical JSON without name, source, method
/// (the resolved numerics count, not the preset they came from), output, end time and the
/// solver controls (newton_*, reuse_contraction, failure_policy,
/// max_halvings), which do not change the problem a state belongs to.
std::string fingerprint(const Scenario& scenario);

}  // namespace fsi
