// Engine::step() reads like the chapter (Sect. 12.3): the geometry of the new level is
// explicit (built from the newest displacement) -> T_m and the old values at T_m ->
// Newton on the monolithic system -> functionals -> report.
#include "fsi/engine.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/contact_release.hpp"
#include "core/corner_barrier.hpp"
#include "core/degeneration.hpp"
#include "core/field_view_builder.hpp"
#include "core/flat_wall_rows.hpp"
#include "core/fsi_system.hpp"
#include "core/functionals.hpp"
#include "core/initial_guess.hpp"
#include "core/parallel_chunks.hpp"
#include "core/rereference.hpp"
#include "core/step_policy.hpp"
#include "core/time_error_estimate.hpp"
#include "core/time_step_choice.hpp"
#include "fe/point_locator.hpp"
#include "fsi/error.hpp"
#include "interface/body.hpp"
#include "interface/step_mapping.hpp"
#include "io/checkpoint.hpp"
#include "io/fingerprint.hpp"
#include "mesh/patch_mesh.hpp"
#include "solve/newton.hpp"

namespace fsi {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct Engine::Impl {
  explicit Impl(Scenario s)
      : scenario((validate(s), std::move(s))),
        mesh(mesh::build_patch_mesh(scenario.mesh, scenario.walls)),
        buckets(mesh),
        system(scenario, mesh),
        newton(system.pattern()),
        barrier_wall_zone_m(corner_barrier_wall_zone_m(scenario)) {
    initialize();
  }

  Scenario scenario;  ///< its numerics may be changed between steps (set_numerics)
  mesh::PatchMesh mesh;
  fe::PatchBuckets buckets;
  core::FsiSystem system;
  solve::NewtonSolver newton;
  State state;
  // Meshes of level m (the current solution's), m-1, and m+1 (built from u^m: the
  // geometry of the next step, and where the body is now).
  fe::CutMesh cut_cur, cut_prev, cut_next;
  /// The body of each sub-element of cut_cur and cut_next (interface::element_bodies).
  std::vector<int> body_cur, body_next;
  fe::CutData data_next;
  fe::QuadratureTable quad_cur;
  /// The longest corner-barrier reach of the scene's bodies where the walls have a convex
  /// corner (a box has none), 0 otherwise: walls, bodies and contact settings are fixed
  /// for a run, so it is found once, not in every step.
  double barrier_wall_zone_m = 0.0;

  static double corner_barrier_wall_zone_m(const Scenario& scenario) {
    double zone_m = 0.0;
    if (scenario.contact.corner_barrier_speed_mps > 0.0)
      for (const BodySpec& body : scene_bodies(scenario))
        if (!core::convex_corners(scenario.walls, {body.center_m.x, body.center_m.y}).empty())
          zone_m = std::max(zone_m, core::corner_barrier_reach_m(scenario, body));
    return zone_m;
  }

  fe::CutOptions cut_options() const {
    return fe::CutOptions{scenario.numerics.cut_snap, scenario.numerics.cut_snap_distance_m,
                          scenario.numerics.cut_align_fraction};
  }

  /// The initial bodies as the state `s` refers its displacement to (core/rereference.hpp).
  std::vector<BodySpec> reference_bodies(const State& s) const {
    const std::span<const BodySpec> scene = scene_bodies(scenario);
    std::vector<BodySpec> bodies(scene.begin(), scene.end());
    if (bodies.size() > 1) {
      for (std::size_t b = 0; b < bodies.size() && b < s.body_references.size(); ++b) {
        bodies[b].center_m.x += s.body_references[b].offset_x_m;
        bodies[b].center_m.y += s.body_references[b].offset_y_m;
        bodies[b].angle_rad += s.body_references[b].rotation_rad;
      }
      return bodies;
    }
    BodySpec& body = bodies[0];
    body.center_m.x += s.reference_offset_x_m;
    body.center_m.y += s.reference_offset_y_m;
    // A shape turned with the body (the ball's d0 does not see it).
    body.angle_rad += s.reference_rotation_rad;
    return bodies;
  }

  /// Takes the body's rigid motion out of u when its rotation exceeds
  /// numerics.rereference_angle_rad (both levels, the same map; the interface does not move).
  /// True if it did.
  bool rereference_if_turned() {
    const double limit = scenario.numerics.rereference_angle_rad;
    if (!(limit > 0.0) || scene_bodies(scenario).size() > 1) return false;
    const core::RigidFit fit = core::fit_rigid_motion(cut_cur, state.solution);
    if (fit.nodes == 0 || std::abs(fit.angle_rad) < limit) return false;
    rereference(fit);
    return true;
  }

  void rereference(const core::RigidFit& fit) {
    core::rereference_displacement(cut_cur, fit, state.solution);
    core::rereference_displacement(cut_prev, fit, state.previous_solution);
    const BodySpec body = reference_bodies(state)[0];
    const mesh::Vec2 centre = core::rereferenced_point(fit, {body.center_m.x, body.center_m.y});
    state.reference_offset_x_m = centre.x() - scene_bodies(scenario)[0].center_m.x;
    state.reference_offset_y_m = centre.y() - scene_bodies(scenario)[0].center_m.y;
    state.reference_rotation_rad += fit.angle_rad;
  }

  /// Several bodies: takes each body's rigid motion out of u after every step, at the
  /// nodes whose initial point is nearest to that body (both levels, the same map per
  /// body; State::body_references). True if there are several bodies.
  bool rereference_bodies() {
    const std::span<const BodySpec> scene = scene_bodies(scenario);
    if (scene.size() < 2) return false;
    const std::vector<BodySpec> bodies = reference_bodies(state);
    const auto regions = [&](const fe::CutMesh& cut, const Eigen::VectorXd& s) {
      std::vector<int> region(cut.x.size());
      for (std::size_t i = 0; i < cut.x.size(); ++i) {
        const mesh::Vec2 u(s[kFieldsPerNode * i + kUx], s[kFieldsPerNode * i + kUy]);
        region[i] = interface::nearest_body(bodies, cut.x[i] - u, -1);  // a tie: left as it is
      }
      return region;
    };
    const std::vector<int> cur_region = regions(cut_cur, state.solution);
    const std::vector<int> prev_region = regions(cut_prev, state.previous_solution);
    state.body_references.resize(scene.size());
    for (std::size_t b = 0; b < scene.size(); ++b) {
      const int body = static_cast<int>(b);
      const std::vector<char> nodes = core::body_nodes(cut_cur, body_cur, body);
      const core::RigidFit fit = core::fit_rigid_motion(cut_cur, state.solution, &nodes);
      if (fit.nodes == 0) continue;
      std::vector<char> cur_nodes(cur_region.size()), prev_nodes(prev_region.size());
      for (std::size_t i = 0; i < cur_region.size(); ++i) cur_nodes[i] = cur_region[i] == body;
      for (std::size_t i = 0; i < prev_region.size(); ++i) prev_nodes[i] = prev_region[i] == body;
      core::rereference_displacement(cut_cur, fit, state.solution, &cur_nodes);
      core::rereference_displacement(cut_prev, fit, state.previous_solution, &prev_nodes);
      const mesh::Vec2 centre = core::rereferenced_point(fit, {bodies[b].center_m.x, bodies[b].center_m.y});
      State::BodyReference& ref = state.body_references[b];
      ref.offset_x_m = centre.x() - scene[b].center_m.x;
      ref.offset_y_m = centre.y() - scene[b].center_m.y;
      ref.rotation_rad += fit.angle_rad;
    }
    return true;
  }

  void initialize() {
    const int n = mesh.num_nodes();
    const std::span<const BodySpec> bodies = scene_bodies(scenario);
    const fe::CutData data0 = fe::cut_data(mesh, [bodies](const mesh::Vec2& x) {
      return interface::scene_distance(bodies, x);
    }, cut_options());
    cut_cur = fe::build_cut_mesh(mesh, data0, cut_options());
    cut_prev = cut_cur;
    state = State{};
    state.time_step_s = scenario.numerics.time_step_s;
    state.time_step_limit_s = scenario.numerics.time_step_s;  // longer steps come after calm ones
    state.solution = Eigen::VectorXd::Zero(kFieldsPerNode * n);
    // The solid moves at its initial velocity, the fluid with it as potential flow
    // (interface::initial_fluid_velocity); the walls hold their nodes at rest below.
    for (int i = 0; i < n; ++i) {
      const Point2 v_solid = bodies[interface::nearest_body(bodies, cut_cur.x[i])].initial_velocity_mps;
      const mesh::Vec2 v = cut_cur.touches_solid[i] ? mesh::Vec2(v_solid.x, v_solid.y)
                                                    : interface::initial_fluid_velocity(bodies, cut_cur.x[i]);
      state.solution[kFieldsPerNode * i + kVx] = v.x();
      state.solution[kFieldsPerNode * i + kVy] = v.y();
    }
    for (int i = 0; i < n; ++i)
      if (mesh.on_wall[i]) state.solution.segment(kFieldsPerNode * i, 2).setZero();
    state.previous_solution = state.solution;
    state.corner_sign = state.previous_corner_sign = data0.corner_sign;
    state.edge_cut = state.previous_edge_cut = data0.edge_cut;
    body_cur = interface::element_bodies(bodies, cut_cur, cut_cur, buckets, state.solution);  // u = 0
    after_state_change();
  }

  /// Rebuilds everything derived from the state: meshes of level m and m-1, the next
  /// geometry and the functionals.
  void rebuild_from_state() {
    cut_cur = fe::build_cut_mesh(mesh, fe::CutData{state.corner_sign, state.edge_cut}, cut_options());
    cut_prev = fe::build_cut_mesh(mesh, fe::CutData{state.previous_corner_sign, state.previous_edge_cut}, cut_options());
    body_cur = interface::element_bodies(reference_bodies(state), cut_cur, cut_prev, buckets, state.previous_solution);
    after_state_change();
  }

  /// Drops the factorization held for the next step: that of a step with the wall's hold
  /// turned round, which restore_factorization() could not rebuild from the state alone
  /// (the next step factorizes afresh, in a continued run and a restored one alike).
  void forget_factorization() {
    newton.reset();
    state.factorization_origin.reset();
  }

  /// Rebuilds the factorization a saved state refers to: the geometry and old values of
  /// the step it was computed in, and the Jacobian at the saved iterate.
  void restore_factorization() {
    newton.reset();
    const std::shared_ptr<const FactorizationOrigin> origin = state.factorization_origin;
    if (!origin) return;
    const State& s0 = origin->step_start;
    const fe::CutMesh cur = fe::build_cut_mesh(mesh, fe::CutData{s0.corner_sign, s0.edge_cut}, cut_options());
    const fe::CutMesh prev = fe::build_cut_mesh(mesh, fe::CutData{s0.previous_corner_sign, s0.previous_edge_cut}, cut_options());
    const std::vector<BodySpec> bodies = reference_bodies(s0);
    const fe::CutMesh next = fe::build_cut_mesh(
        mesh, fe::cut_data(mesh, interface::ips_level_set(bodies, cur, buckets, s0.solution), cut_options()), cut_options());
    const fe::QuadratureTable quad = fe::build_quadrature(next);
    const std::vector<int> next_body = interface::element_bodies(bodies, next, cur, buckets, s0.solution);
    system.set_element_bodies(next_body);
    system.set_geometry(next, quad, origin->time_step_s);
    set_step_rules(s0);
    std::vector<forms::OldValues> old;
    interface::MappingOptions mo = mapping_options(origin->time_step_s);
    mo.element_body = &next_body;
    interface::compute_old_values(mesh, buckets, next, quad, {&cur, &s0.solution}, {&prev, &s0.previous_solution},
                                  bodies, scenario.walls, mo, old);
    system.set_old_values(std::move(old));
    release_wall_nodes(s0, cur, next);
    newton.factorize_at(system, origin->iterate);
  }

  /// Newton's start on cut_next (core/initial_guess.hpp: moved nodes re-interpolated,
  /// the solid field where that start would be unphysical).
  Eigen::VectorXd initial_guess() const {
    return core::initial_guess(mesh, buckets, cut_cur, cut_next, state.solution, nullptr,
                               core::StartMode::repair_unphysical);
  }

  interface::MappingOptions mapping_options(double k) const {
    interface::MappingOptions mo;
    mo.k_s = k;
    mo.eps_patches = scenario.numerics.blend_eps_patches;
    mo.delta_patches = scenario.numerics.blend_delta_patches;
    mo.identity_gap_m = scenario.numerics.identity_gap_m;
    mo.threads = core::resolve_threads(scenario.numerics.assembly_threads);
    return mo;
  }

  void after_state_change() {
    quad_cur = fe::build_quadrature(cut_cur);
    next_geometry();
  }

  /// cut_next, its bodies and the functionals of the state, from cut_cur and u^m.
  void next_geometry() {
    const std::vector<BodySpec> bodies = reference_bodies(state);
    data_next = fe::cut_data(mesh, interface::ips_level_set(bodies, cut_cur, buckets, state.solution), cut_options());
    cut_next = fe::build_cut_mesh(mesh, data_next, cut_options());
    body_next = interface::element_bodies(bodies, cut_next, cut_cur, buckets, state.solution);
    state.functionals = core::compute_functionals(scenario, cut_next, cut_cur, quad_cur, state.solution,
                                                    state.reference_rotation_rad, body_next, body_cur,
                                                    state.body_references);
  }

  /// The FE function `coeffs` of `cut` (another mesh's) at every node position `x` of
  /// this mesh's cut mesh: nodal interpolation onto this mesh.
  static Eigen::VectorXd sample(const fe::CutMesh& cut, const fe::PatchBuckets& cut_buckets,
                                const Eigen::VectorXd& coeffs, const std::vector<mesh::Vec2>& x) {
    Eigen::VectorXd out(kFieldsPerNode * static_cast<Eigen::Index>(x.size()));
    for (std::size_t n = 0; n < x.size(); ++n) {
      const fe::Location loc = fe::locate(cut, cut_buckets, x[n], 1e-6);
      if (loc.element < 0) {
        std::ostringstream where;
        where << "node " << n << " at (" << x[n].x() << ", " << x[n].y()
              << ") m of the new mesh lies outside the old mesh: a remeshed run needs the same domain";
        throw InputError("<remesh>", "/mesh", where.str());
      }
      for (int f = 0; f < kFieldsPerNode; ++f)
        out[kFieldsPerNode * static_cast<Eigen::Index>(n) + f] = fe::evaluate(cut, loc, coeffs, kFieldsPerNode, f);
    }
    return out;
  }

  /// Takes over `src`'s run on this mesh. Level m's geometry is built here the way the step
  /// that made it built it on the old mesh: the cut of the IPS level set of u^{m-1}
  /// (12.4). Level m-1's geometry would need u^{m-2}, which no state keeps: it is taken
  /// equal to level m's (the level m-1 solution itself is interpolated exactly as level
  /// m's), as at t = 0. That changes only where the previous displacement has its kink,
  /// by the interface's motion in one step. Both solutions are interpolated at this mesh's
  /// node positions (moved nodes included); where the meshes share nodes nothing changes.
  void remesh_from(const Impl& src) {
    const std::vector<BodySpec> src_bodies = src.reference_bodies(src.state);
    const fe::CutData data = fe::cut_data(
        mesh, interface::ips_level_set(src_bodies, src.cut_prev, src.buckets, src.state.previous_solution),
        cut_options());
    const fe::CutMesh cut = fe::build_cut_mesh(mesh, data, cut_options());
    State s;
    s.time_s = src.state.time_s;
    s.step = src.state.step;
    s.time_step_s = src.state.time_step_s;
    s.time_step_limit_s = src.state.time_step_limit_s;
    s.reference_offset_x_m = src.state.reference_offset_x_m;
    s.reference_offset_y_m = src.state.reference_offset_y_m;
    s.reference_rotation_rad = src.state.reference_rotation_rad;
    s.body_references = src.state.body_references;
    s.solution = sample(src.cut_cur, src.buckets, src.state.solution, cut.x);
    s.previous_solution = sample(src.cut_prev, src.buckets, src.state.previous_solution, cut.x);
    for (int i = 0; i < mesh.num_nodes(); ++i)
      if (mesh.on_wall[i]) {  // no-slip, as every step leaves it (interpolation gives 0 up to rounding)
        s.solution.segment(kFieldsPerNode * i, 2).setZero();
        s.previous_solution.segment(kFieldsPerNode * i, 2).setZero();
      }
    s.corner_sign = s.previous_corner_sign = data.corner_sign;
    s.edge_cut = s.previous_edge_cut = data.edge_cut;
    state = std::move(s);  // no factorization_origin: the first step factorizes afresh
    newton.reset();
    rebuild_from_state();
  }

  int last_ips_failures = 0;  ///< of the latest attempt (diagnostics for the step report)
  bool last_attempt_in_contact = false;  ///< a wall node touched the solid in the latest attempt

  /// What the system's assembly takes from the state at a step's start besides the
  /// geometry: the cavitation floor (off for the first step of a moving start); with the
  /// old values, release_wall_nodes(). Also for the step a restored factorization was
  /// computed in, so that it is rebuilt bit for bit.
  void set_step_rules(const State& start) {
    // The first step of a body that starts moving adapts its initial flow (the potential
    // flow of interface::initial_fluid_velocity) to the walls: its pressure is an impulse
    // of order rho_f |dv| L / k (+-5e4 Pa across the U-box of
    // assets/scenarios/impacts/side_wall_throw.json at k = 2e-3 s), not the suction of a
    // film, and under the floor of -1e4 Pa Newton made no progress on it at any halving
    // (ThrownBall.*). From the second step on the flow moves with the body (-5e3 Pa behind
    // that ball at step 5) and the floor acts.
    system.set_cavitation_floor(!(start.step == 0 && starts_moving()));
  }

  /// The wall nodes the solid lets go of this step (core/contact_release.hpp), from the
  /// wall's force on the state at the step's start (geometry `cur`), on the step's geometry
  /// `next` and old values (set before). Only in real contact: one residual more per step.
  /// With `turned`, the other way round: the nodes it holds are released and the
  /// released held (the retry of a step that did not converge in real contact, at the
  /// same start, length and geometry as the attempt before it, whose decision it turns
  /// round instead of assembling the wall's force again).
  /// Returns whether some wall node touches the solid.
  bool release_wall_nodes(const State& start, const fe::CutMesh& cur, const fe::CutMesh& next, bool turned = false) {
    system.set_released_nodes({});
    bool touching = false;
    for (std::size_t n = 0; n < mesh.nodes.size() && !touching; ++n)
      touching = mesh.on_wall[n] && next.touches_solid[n];
    if (!touching) return false;
    if (turned) {
      system.set_released_nodes(core::turned_round(mesh, next.touches_solid, released_by_wall_force));
      return true;
    }
    Eigen::VectorXd wall_force;
    system.unconstrained_residual(start.solution, wall_force);
    released_by_wall_force = core::released_wall_nodes(mesh, next.touches_solid, cur.touches_solid, wall_force);
    system.set_released_nodes(released_by_wall_force);
    return true;
  }
  /// The decision of the latest release_wall_nodes() from the wall's force.
  std::vector<char> released_by_wall_force;

  /// Whether the body has an initial velocity (its first step is an impulsive start).
  bool starts_moving() const {
    for (const BodySpec& body : scene_bodies(scenario))
      if (body.initial_velocity_mps.x != 0.0 || body.initial_velocity_mps.y != 0.0) return true;
    return false;
  }

  /// One attempt at a step of size k on the geometry cut_next. Does not touch the state.
  solve::NewtonResult attempt(double k, const fe::QuadratureTable& quad, Eigen::VectorXd& x,
                              StepReport& report, bool contact_turned = false) {
    auto t0 = std::chrono::steady_clock::now();
    system.set_element_bodies(body_next);
    system.set_geometry(cut_next, quad, k);
    set_step_rules(state);
    report.geometry_seconds += seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    interface::MappingOptions mo = mapping_options(k);
    mo.element_body = &body_next;
    std::vector<forms::OldValues> old;
    const interface::MappingStats ms = interface::compute_old_values(
        mesh, buckets, cut_next, quad, {&cut_cur, &state.solution}, {&cut_prev, &state.previous_solution},
        reference_bodies(state), scenario.walls, mo, old);
    system.set_old_values(std::move(old));
    report.mapping_seconds += seconds_since(t0);
    last_attempt_in_contact = release_wall_nodes(state, cut_cur, cut_next, contact_turned);
    last_ips_failures = ms.ips_failures;  // reported once, for the attempt that counts

    x = initial_guess();
    // The first step of a moving start ends with an impulse for pressure (set_step_rules),
    // no guess for the second step's: from it, under the floor, Newton started at a
    // residual of 7.6e3 and did not converge within 4 halvings on the coarse U-box of
    // ThrownBall.*; from p = 0 every step there converges.
    if (state.step == 1 && starts_moving())
      for (Eigen::Index i = kP; i < x.size(); i += kFieldsPerNode) x[i] = 0.0;
    solve::NewtonOptions no;
    no.budget = scenario.numerics.newton_budget;
    no.rel_tol = scenario.numerics.newton_rel_tol;
    no.abs_tol = scenario.numerics.newton_abs_tol;
    no.reuse_contraction = scenario.numerics.reuse_contraction;
    no.krylov_max_iterations = scenario.numerics.krylov_iterations;
    no.lu_threads = core::resolve_threads(scenario.numerics.assembly_threads);
    // In real contact the cut changes from step to step by slivers beside the wall nodes
    // the body holds, and the previous step's factorization starts Newton off at residuals
    // up to 6.6e6: 120 steps of Example 1 from t = 4.782 s took 3.45 iterations and 1.65
    // factorizations per step with it, 2.02 and 1.43 with a factorization at each step's
    // start (docs/solver.md, "Reuse").
    no.reuse_across_steps = wall_node_in_body().first < 0;
    solve::NewtonResult r = newton.solve(system, x, no);
    if (r.factorization_point.size() > 0) {
      // Remember what determines the factorization now held, so a restored state can
      // rebuild it exactly (bit-identical continuation, see FactorizationOrigin).
      auto origin = std::make_shared<FactorizationOrigin>();
      origin->step_start = state;
      origin->step_start.factorization_origin.reset();
      origin->iterate = std::move(r.factorization_point);
      origin->time_step_s = k;
      state.factorization_origin = std::move(origin);
    }
    report.newton_iterations += r.iterations;
    report.factorizations += r.factorizations;
    report.jacobian_assemblies += r.jacobians;
    report.krylov_iterations += r.krylov_iterations;
    report.residual_norms.insert(report.residual_norms.end(), r.norms.begin(), r.norms.end());
    report.assembly_seconds += r.assembly_seconds;
    report.factorization_seconds += r.factorization_seconds;
    report.solve_seconds += r.solve_seconds;
    return r;
  }

  /// What a step's solution x (on cut_next) would make of the body: the geometry of the
  /// step after it and the functionals, computed as accept() computes them.
  struct Outcome {
    fe::CutData data_next;
    fe::CutMesh cut_next;
    std::vector<int> body_next;  ///< the bodies of cut_next's sub-elements
    Functionals functionals;
  };
  Outcome outcome_of(const Eigen::VectorXd& x, const fe::QuadratureTable& quad) const {
    Outcome o;
    const std::vector<BodySpec> bodies = reference_bodies(state);
    o.data_next = fe::cut_data(mesh, interface::ips_level_set(bodies, cut_next, buckets, x), cut_options());
    o.cut_next = fe::build_cut_mesh(mesh, o.data_next, cut_options());
    o.body_next = interface::element_bodies(bodies, o.cut_next, cut_next, buckets, x);
    o.functionals = core::compute_functionals(scenario, o.cut_next, cut_next, quad, x, state.reference_rotation_rad,
                                              o.body_next, body_next, state.body_references);
    return o;
  }

  /// Whether x of a step of length k broke the body (core/degeneration.hpp).
  std::optional<core::Degeneration> degeneration(const Eigen::VectorXd& x, double k, const fe::QuadratureTable& quad,
                                                 const Outcome& o) const {
    if (std::optional<core::Degeneration> merged = core::merged_bodies(o.cut_next, o.body_next)) return merged;
    if (std::optional<core::Degeneration> open = core::body_at_open_boundary(mesh, o.cut_next)) return open;
    const core::SolidDeterminant det = core::solid_determinant(cut_next, quad, x);
    const core::CutPatchScale patch = core::largest_cut_patch(mesh, cut_next, o.cut_next);
    std::optional<core::Degeneration> d = core::detect_degeneration(
        state.functionals, o.functionals, k, patch.side_m, det.non_positive, {det.where.x(), det.where.y()},
        patch.area_m2);
    if (d && det.non_positive > 0) d->cause += core::flat_wall_row_note(mesh, d->where_m);
    return d;
  }

  void accept(Eigen::VectorXd&& x, double k, fe::QuadratureTable&& quad_next, Outcome&& outcome, StepReport& report) {
    state.previous_solution = std::move(state.solution);
    state.solution = std::move(x);
    state.previous_corner_sign = std::move(state.corner_sign);
    state.previous_edge_cut = std::move(state.edge_cut);
    state.corner_sign = data_next.corner_sign;
    state.edge_cut = data_next.edge_cut;
    state.time_s += k;
    state.step += 1;
    state.time_step_s = k;
    cut_prev = std::move(cut_cur);
    cut_cur = std::move(cut_next);
    quad_cur = std::move(quad_next);  // the step's quadrature becomes the current one: no copy
    body_cur = std::move(body_next);
    const auto t0 = std::chrono::steady_clock::now();
    if (rereference_bodies() || rereference_if_turned()) {  // the same interface up to rounding, in the new reference
      next_geometry();
    } else {
      data_next = std::move(outcome.data_next);
      cut_next = std::move(outcome.cut_next);
      body_next = std::move(outcome.body_next);
      state.functionals = outcome.functionals;
    }
    report.geometry_seconds += seconds_since(t0);
    report_contact(report);
  }

  /// Real contact: a wall node inside the body (or on its interface) in the geometry
  /// cut_next. Returns the node and its wall, {-1, -1} if there is none.
  std::pair<int, int> wall_node_in_body() const {
    for (const mesh::GridEdge& e : mesh.edges) {
      if (e.wall < 0) continue;
      for (int n : {e.a, e.b})
        if (cut_next.corner_sign[n] <= 0) return {n, e.wall};
    }
    return {-1, -1};
  }

  /// ", body1 and body2 push each other apart (gap ... m)" when the penalty acts between
  /// two bodies this step; empty otherwise.
  std::string bodies_in_contact() const {
    const std::array<int, 2> b = system.closest_bodies();
    if (b[0] < 0 || b[1] < 0 || !(system.min_body_gap() < scenario.contact.dist0_m)) return "";
    return ", body" + std::to_string(std::min(b[0], b[1]) + 1) + " and body" + std::to_string(std::max(b[0], b[1]) + 1) +
           " push each other apart (gap " + std::to_string(system.min_body_gap()) + " m)";
  }

  void report_contact(StepReport& report) const {
    const auto [n, wall] = wall_node_in_body();
    if (n < 0) return;
    report.events.push_back({StepEvent::Kind::real_contact, state.time_s, {mesh.nodes[n].x(), mesh.nodes[n].y()}, wall,
                             "real contact: the body touches wall " + std::to_string(wall)});
  }

  /// Where the attempt's final residual peaks, on the geometry it was solved on (cut_next:
  /// call before accept() moves it).
  ResidualPeak residual_peak(const solve::NewtonResult& r) const {
    ResidualPeak p;
    if (r.worst_row < 0) return p;
    const int node = static_cast<int>(r.worst_row / kFieldsPerNode);
    p.node = node;
    p.equation = static_cast<Field>(r.worst_row % kFieldsPerNode);
    p.where_m = {cut_next.x[node].x(), cut_next.x[node].y()};
    const bool solid = cut_next.touches_solid[node], fluid = cut_next.touches_fluid[node];
    p.phase = solid && fluid ? "interface" : solid ? "solid" : "fluid";
    p.scaled_value = r.worst_value;
    return p;
  }

  /// What the attempts at one step leave behind for the step's report: the best attempt
  /// so far (halve_step keeps the one that reduced its residual most, relative to its own
  /// start, both in one row scale: when every halving fails too, that one is accepted and
  /// flagged, never simply the last, since after real contact smaller steps can do worse;
  /// what counts as an attempt to keep: core::judge_attempt), why an unconverged step was
  /// accepted as it is or rejected, and the residuals of the attempt kept.
  struct StepAttempts {
    Eigen::VectorXd best_x;
    double best_k = 0.0;
    double best_reduction = std::numeric_limits<double>::infinity();
    double best_final = std::numeric_limits<double>::infinity();  ///< its last scaled residual
    double best_first = std::numeric_limits<double>::infinity();  ///< its first
    ResidualPeak best_peak;
    std::optional<Outcome> best_outcome;
    bool best_turned = false;
    std::string policy_note;  ///< why an unconverged step was accepted as it is, or rejected
    /// The residual of the attempt the step keeps, for the message: report.residual_norms
    /// runs through every attempt, so its last entry is the last attempt's, which after
    /// accept_best is not the one accepted.
    double kept_first = std::numeric_limits<double>::quiet_NaN();
    double kept_last = std::numeric_limits<double>::quiet_NaN();
    std::optional<core::Degeneration> broken;  ///< of the latest attempt that broke the body
    int halvings = 0;
    /// In real contact a step that does not converge is first tried again at the same
    /// length with the wall's hold turned round (release_wall_nodes): the hold is decided
    /// explicitly from the step's start, and where the wall's force is about to change
    /// sign it can pick the wrong side. The side wall throw of assets/scenarios/impacts/
    /// held its contact patch at t = 1.183 s as the ball left the wall and did not
    /// converge at any halving; released, that step converged (docs/method.md, "Letting
    /// go of a wall").
    bool contact_turned = false;
  };

  /// The body of each node of `cut` (-1: in no solid sub-element) from its sub-elements'
  /// bodies; empty with one body.
  std::vector<int> node_bodies(const fe::CutMesh& cut, const std::vector<int>& element_body) const {
    if (scene_bodies(scenario).size() < 2 || element_body.size() != cut.elements.size()) return {};
    std::vector<int> node_body(cut.x.size(), -1);
    for (std::size_t k = 0; k < cut.elements.size(); ++k)
      if (element_body[k] >= 0)
        for (int a = 0; a < cut.elements[k].vertices; ++a) node_body[cut.elements[k].node[a]] = element_body[k];
    return node_body;
  }

  /// The numerics the step length is chosen with: the wall zone at least the contact
  /// force's and the corner barrier's reach (NumericsSpec::time_step_wall_zone_m).
  NumericsSpec step_length_numerics() const {
    NumericsSpec n = scenario.numerics;
    if (scenario.contact.gamma_c > 0.0) n.time_step_wall_zone_m = std::max(n.time_step_wall_zone_m, scenario.contact.dist0_m);
    n.time_step_wall_zone_m = std::max(n.time_step_wall_zone_m, barrier_wall_zone_m);
    return n;
  }

  /// One step: its length, the attempts at it (retries and failure policy in
  /// run_attempts), the report.
  StepReport step() {
    StepReport report;
    double k = core::choose_time_step(
        step_length_numerics(), state.functionals, core::cut_patch_side(mesh, cut_next), state.time_s,
        state.time_step_limit_s,
        core::solid_motion(cut_cur, state.solution, cut_prev, state.previous_solution, state.time_step_s));
    fe::QuadratureTable quad = fe::build_quadrature(cut_next);
    StepAttempts attempts;
    attempts.best_k = k;
    run_attempts(k, quad, report, attempts);
    if (system.max_contact_pressure() > 0.0)
      report.events.push_back({StepEvent::Kind::contact_force_active, state.time_s, {}, -1,
                               std::string(system.corner_barrier_acted() ? "penalty contact or corner barrier active"
                                                                         : "penalty contact active") +
                                   ", max pressure " +
                                   std::to_string(system.max_contact_pressure()) + " Pa, force on the body (" +
                                   std::to_string(system.contact_force_on_body().x()) + ", " +
                                   std::to_string(system.contact_force_on_body().y()) + ") N/m" +
                                   bodies_in_contact()});
    finish_report(k, attempts, report);
    return report;
  }

  /// Attempts at the step of length k until one is accepted, the best is accepted or the
  /// step is rolled back (numerics.failure_policy); k ends as the accepted length.
  void run_attempts(double& k, fe::QuadratureTable& quad, StepReport& report, StepAttempts& a) {
    const bool may_halve = scenario.numerics.failure_policy == FailurePolicy::halve_step;
    for (int attempt_no = 0;; ++attempt_no) {
      Eigen::VectorXd x;
      const solve::NewtonResult r = attempt(k, quad, x, report, a.contact_turned);
      const bool finite = !r.non_finite && x.allFinite();
      report.largest_residual = residual_peak(r);
      report.converged = r.converged && finite;
      core::AttemptVerdict verdict = core::judge_attempt(scenario.numerics, r, finite, a.halvings, a.best_x.size() > 0);
      std::optional<Outcome> outcome;
      const bool this_broke = check_body(x, k, quad, may_halve, verdict, outcome, report, a);
      if (verdict.candidate && r.relative_residual < a.best_reduction) {
        a.best_reduction = r.relative_residual;
        a.best_final = r.norms.empty() ? std::numeric_limits<double>::infinity() : r.norms.back();
        a.best_first = r.norms.empty() ? std::numeric_limits<double>::infinity() : r.norms.front();
        a.best_x = x;
        a.best_k = k;
        a.best_peak = report.largest_residual;
        a.best_outcome = outcome;
        a.best_turned = a.contact_turned;
      }
      if (verdict.action == core::AttemptAction::accept) {
        accept_attempt(std::move(x), k, quad, std::move(*outcome), r, attempt_no, verdict, report, a);
        return;
      }
      const std::string why_retry = this_broke ? "the body broke" : "Newton did not converge";
      if (verdict.action == core::AttemptAction::retry_halved && attempt_no == 0 && last_attempt_in_contact) {
        a.contact_turned = true;
        report.events.push_back({StepEvent::Kind::contact_retried, state.time_s, {}, -1,
                                 why_retry + " in real contact: retrying with the wall's hold turned round"});
        continue;
      }
      a.contact_turned = false;  // the halvings hold as decided
      if (verdict.action == core::AttemptAction::retry_halved) {
        ++a.halvings;
        k *= 0.5;
        report.events.push_back({StepEvent::Kind::step_halved, state.time_s, {}, -1,
                                 why_retry + ": retrying with k = " + std::to_string(k)});
        continue;
      }
      if (verdict.action == core::AttemptAction::accept_best) {
        accept_best_attempt(k, quad, attempt_no, report, a);
        return;
      }
      give_up(r, finite, report, a);
      return;
    }
  }

  /// A solution the step would keep (now, or later as the best attempt) must leave a
  /// sound body: its outcome is computed, and a broken one is retried shorter (halve_step)
  /// or rolled back (verdict changed so). True if the attempt broke the body.
  bool check_body(const Eigen::VectorXd& x, double k, const fe::QuadratureTable& quad, bool may_halve,
                  core::AttemptVerdict& verdict, std::optional<Outcome>& outcome, StepReport& report,
                  StepAttempts& a) {
    if (verdict.action != core::AttemptAction::accept && !verdict.candidate) return false;
    const auto t0 = std::chrono::steady_clock::now();
    outcome = outcome_of(x, quad);
    std::optional<core::Degeneration> d = degeneration(x, k, quad, *outcome);
    report.geometry_seconds += seconds_since(t0);
    if (!d) return false;
    const bool outside = d->outside_domain;
    if (!outside) report.converged = false;  // a body that leaves the domain may be solved well
    report.events.push_back({outside ? StepEvent::Kind::left_domain : StepEvent::Kind::degenerated, state.time_s + k,
                             d->where_m, -1,
                             "the solution of a step of " + std::to_string(k) + " s " +
                                 (outside ? "takes the body out of the domain: " : "broke the body: ") + d->cause});
    a.broken = std::move(d);
    outcome.reset();
    verdict.candidate = false;
    verdict.flagged_early = false;
    if (outside)
      verdict.action = core::AttemptAction::give_up;  // a shorter step only delays it
    else if (may_halve && a.halvings < scenario.numerics.max_halvings)
      verdict.action = core::AttemptAction::retry_halved;
    else if (may_halve && a.best_x.size() > 0)
      verdict.action = core::AttemptAction::accept_best;
    else
      verdict.action = core::AttemptAction::give_up;
    return true;
  }

  /// The attempt converged (or is accepted flagged at once): the state moves on, and the
  /// next step's limit follows from how this one went (and from the time error).
  void accept_attempt(Eigen::VectorXd x, double k, fe::QuadratureTable& quad, Outcome outcome,
                      const solve::NewtonResult& r, int attempt_no, const core::AttemptVerdict& verdict,
                      StepReport& report, StepAttempts& a) {
    if (!r.norms.empty()) a.kept_first = r.norms.front(), a.kept_last = r.norms.back();
    const double tolerance_m = scenario.numerics.time_error_tolerance_m;
    if (tolerance_m > 0.0 && state.step >= 1)
      report.time_error_m = core::displacement_error_estimate(cut_prev, state.previous_solution, cut_cur,
                                                              state.solution, cut_next, x, state.time_step_s, k,
                                                              node_bodies(cut_next, body_next));
    accept(std::move(x), k, std::move(quad), std::move(outcome), report);
    if (a.contact_turned) forget_factorization();
    report.accepted = true;
    state.time_step_limit_s = core::next_time_step_limit(
        {k, attempt_no == 0 && report.converged, r.iterations}, scenario.numerics.time_step_s);
    if (report.time_error_m >= 0.0)
      state.time_step_limit_s =
          std::min(state.time_step_limit_s, core::step_for_error(k, report.time_error_m, tolerance_m));
    if (verdict.flagged_early) {
      std::ostringstream why;
      why << "accepted without halving: residual at " << r.relative_residual
          << " of its start (accept_flagged_reduction), " << r.norms.back()
          << " scaled (accept_flagged_max_residual)";
      a.policy_note = why.str();
    }
  }

  /// Every halving failed: the best attempt is accepted and flagged, unless it solves
  /// nothing (numerics.accept_best_max_residual), when the step is rolled back.
  void accept_best_attempt(double& k, fe::QuadratureTable& quad, int attempt_no, StepReport& report,
                           StepAttempts& a) {
    const double bound = scenario.numerics.accept_best_max_residual;
    if (bound > 0.0 && !(a.best_final <= bound)) {
      // The best attempt solves nothing: stop here rather than go on from it.
      report.accepted = false;
      std::ostringstream why;
      why << "no attempt got below accept_best_max_residual = " << bound << " (the best ended at "
          << a.best_final << " scaled): rolled back to the state before the step";
      report.events.push_back({StepEvent::Kind::rolled_back, state.time_s, {}, -1, why.str()});
      a.policy_note = why.str();
      return;
    }
    std::ostringstream why;
    why << "accepted the best of " << attempt_no + 1 << " attempt(s), k = " << a.best_k << " s";
    a.policy_note = why.str();
    a.kept_first = a.best_first, a.kept_last = a.best_final;
    k = a.best_k;
    report.largest_residual = a.best_peak;
    report.converged = false;
    accept(std::move(a.best_x), k, std::move(quad), std::move(*a.best_outcome), report);
    if (a.best_turned || a.contact_turned) forget_factorization();  // kept or held last
    report.accepted = true;
    state.time_step_limit_s = core::next_time_step_limit({k, false, 0}, scenario.numerics.time_step_s);
  }

  /// The step is rolled back: stop_and_rollback, no attempt that moved Newton's iterate,
  /// a non-finite result (NaN/Inf never leaves the engine), or a broken body.
  void give_up(const solve::NewtonResult& r, bool finite, StepReport& report, StepAttempts& a) {
    report.accepted = false;
    std::string why = "rolled back to the state before the step";
    if (a.broken && a.broken->outside_domain) {
      why = "the step takes the body out of the domain (" + a.broken->cause + "): " + why;
      a.policy_note = a.broken->cause;
    } else if (a.broken) {
      std::ostringstream b;
      b << "the step broke the body (" << a.broken->cause << ", at (" << a.broken->where_m.x << ", "
        << a.broken->where_m.y << ") m): " << why;
      why = b.str();
      a.policy_note = "the body broke: " + a.broken->cause;
    } else if (finite && !core::made_progress(r) && scenario.numerics.failure_policy != FailurePolicy::stop_and_rollback) {
      why = "Newton made no progress (no iterate reduced the residual; accepting would freeze the body): " + why;
    }
    report.events.push_back({finite ? StepEvent::Kind::rolled_back : StepEvent::Kind::non_finite,
                             state.time_s, {}, -1,
                             finite ? why : "non-finite values: step rejected, state rolled back"});
    if (!a.broken && finite && !core::made_progress(r)) a.policy_note = "Newton made no progress";
  }

  /// The report's message, length and time once the step is decided.
  void finish_report(double k, const StepAttempts& a, StepReport& report) const {
    report.message = a.policy_note;
    if (last_ips_failures > 0)
      report.message += (report.message.empty() ? "" : "; ") + std::to_string(last_ips_failures) +
                        " IPS point(s) did not converge";
    report.time_step_s = k;
    report.time_s = state.time_s;
    std::ostringstream msg;
    msg << (report.converged ? "converged" : "NOT converged") << " in " << report.newton_iterations
        << " Newton iteration(s), " << report.factorizations << " factorization(s)";
    if (report.krylov_iterations > 0) msg << ", " << report.krylov_iterations << " GMRES iteration(s)";
    if (report.accepted && std::isfinite(a.kept_first))
      msg << ", residual " << a.kept_first << " -> " << a.kept_last;
    else if (!report.residual_norms.empty())
      msg << ", residual " << report.residual_norms.front() << " -> " << report.residual_norms.back();
    if (const ResidualPeak& w = report.largest_residual; !report.converged && w.node >= 0)
      msg << "; largest residual: " << equation_name(w.equation) << " at node " << w.node << " ("
          << w.where_m.x << ", " << w.where_m.y << ") m, " << w.phase;
    if (!report.accepted) msg << "; step rejected";
    report.message = msg.str() + (report.message.empty() ? "" : "; " + report.message);
  }
};

const char* equation_name(Field row) {
  switch (row) {
    case kVx: return "momentum x";
    case kVy: return "momentum y";
    case kUx: return "displacement x";
    case kUy: return "displacement y";
    case kP: return "continuity";
  }
  return "?";
}

Engine::Engine(Scenario scenario) : impl_(std::make_unique<Impl>(std::move(scenario))) {}
Engine::~Engine() = default;
Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;

StepReport Engine::step() { return impl_->step(); }
const State& Engine::state() const { return impl_->state; }
const Scenario& Engine::scenario() const { return impl_->scenario; }
void Engine::set_numerics(const NumericsSpec& numerics) {
  Scenario changed = impl_->scenario;  // same checks as a scenario file's numerics
  changed.numerics = numerics;
  validate(changed);
  // The scenario is the one record of the numerics in use: scenario() reports them and a
  // checkpoint saved from now on carries their fingerprint (and loads only into an
  // engine that runs them).
  impl_->scenario.numerics = numerics;
  impl_->system.set_numerics(numerics);  // stabilization weights live in the system
}

void Engine::set_state(const State& state) {
  const std::size_t n = impl_->mesh.num_nodes(), e = impl_->mesh.edges.size();
  if (state.solution.size() != static_cast<Eigen::Index>(kFieldsPerNode * n) ||
      state.previous_solution.size() != state.solution.size() || state.corner_sign.size() != n ||
      state.previous_corner_sign.size() != n || state.edge_cut.size() != e || state.previous_edge_cut.size() != e)
    throw InputError("<state>", "", "state does not fit this scenario's mesh (" + std::to_string(n) + " nodes)");
  if (!state.solution.allFinite() || !state.previous_solution.allFinite())
    throw InputError("<state>", "/solution", "contains non-finite values");
  impl_->state = state;
  impl_->restore_factorization();
  impl_->rebuild_from_state();
}

void Engine::remesh_from(const Engine& source) {
  // Everything but the mesh must be the same: compare the fingerprints (physics and
  // discretization, not the solver controls) with this engine's mesh put into the source's.
  Scenario same = source.scenario();
  same.mesh = impl_->scenario.mesh;
  if (fingerprint(same) != fingerprint(impl_->scenario))
    throw InputError("<remesh>", "", "the new scenario differs from the run's in more than its mesh "
                                     "(body, walls, materials, contact and numerics must be the same)");
  impl_->remesh_from(*source.impl_);
}

double Engine::rereference() {
  Impl& e = *impl_;
  if (scene_bodies(e.scenario).size() > 1) {  // every body, each in its own region
    const double before = e.state.body_references.empty() ? 0.0 : e.state.body_references[0].rotation_rad;
    e.rereference_bodies();
    e.after_state_change();
    return e.state.body_references[0].rotation_rad - before;
  }
  const core::RigidFit fit = core::fit_rigid_motion(e.cut_cur, e.state.solution);
  if (fit.nodes == 0) return 0.0;
  e.rereference(fit);
  e.after_state_change();  // the same cut up to rounding; the functionals of the new u
  return fit.angle_rad;
}

FieldView Engine::view() const {
  return core::build_field_view(impl_->mesh, impl_->cut_cur, impl_->state, impl_->scenario, impl_->body_cur);
}

}  // namespace fsi

namespace fsi {

void save_checkpoint(const Engine& engine, const std::filesystem::path& file) {
  io::write_checkpoint(file, engine.state(), fingerprint(engine.scenario()));
}

void load_checkpoint(Engine& engine, const std::filesystem::path& file) {
  const State state =
      io::read_checkpoint(file, fingerprint(engine.scenario()), io::fingerprint_v3(engine.scenario()));
  try {
    engine.set_state(state);
  } catch (const InputError& e) {
    throw InputError(file.string(), e.key(), e.why());
  }
}

}  // namespace fsi
