#pragma once
/// \file scenario_schema.hpp
/// The one description of the scenario file: for every member of every Scenario struct,
/// its JSON key and the values it may take. The JSON reader, the JSON writer and
/// validate() all walk this description, so key names and allowed ranges cannot drift
/// apart. JSON keys equal the member names.
///
/// A visitor is called as `v(key, member, rule)`; `rule` says what is allowed:
///   Real   a finite double (also each coordinate of a Point2 / Segment2 / corner array)
///   Int    an integer        Flag  true/false        Choice  one of a few names
///   Name   a scenario name   Fields  a nested struct  List<R>  an array of R-items
/// A std::optional member with Fields is an object that may be left out.
#include <array>
#include <concepts>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "fsi/scenario.hpp"

namespace fsi::io {

/// A finite real in an interval; `unit` is printed after the interval.
struct Real {
  double lo;
  double hi;
  bool lo_open = false;
  bool hi_open = false;
  const char* unit = "";
  bool contains(double value) const;
  /// e.g. "(0, 1] s"
  std::string text() const;
};

/// An integer in [lo, hi].
struct Int {
  long lo;
  long hi;
};

struct Flag {};
struct Fields {};

/// A scenario name: 1..128 characters from [A-Za-z0-9_.+=-], so it can name files.
struct Name {
  static constexpr std::size_t kMaxLength = 128;
  static bool valid_char(char c);
};

/// One of a fixed set of names (enums are stored by name).
struct Choice {
  std::span<const std::string_view> names;
  std::string text() const;  ///< e.g. "one of \"vx\", \"vy\""
};

/// An array of between `min` and `max` entries, each following `item`.
template <class ItemRule>
struct List {
  std::size_t min;
  std::size_t max;
  ItemRule item;
};

inline constexpr std::array<std::string_view, 3> kFailurePolicyNames{
    "accept_and_flag", "halve_step", "stop_and_rollback"};
/// In the order of fsi::Method.
inline constexpr std::array<std::string_view, 2> kMethodNames{"fsi", "chapter"};
inline constexpr std::array<std::string_view, 5> kOutputFieldNames{"vx", "vy", "vmag", "p", "umag"};
/// In the order of fsi::BodyShape.
inline constexpr std::array<std::string_view, 3> kBodyShapeNames{"circle", "ellipse", "rounded_rectangle"};

/// Bodies in one scene.
inline constexpr std::size_t kMaxBodies = 8;

/// Coordinates and lengths: a generous box around any lab-scale set-up, and far from
/// the range where squaring a coordinate could overflow.
inline constexpr Real kCoordinate{-1.0e3, 1.0e3, false, false, "m"};

/// Keys an array item must spell out (top-level sections and their members default to
/// Example 1; a default for one piece of a mesh axis would be a guess).
inline std::span<const std::string_view> required_keys(const void*) { return {}; }
inline std::span<const std::string_view> required_keys(const AxisPiece*) {
  static constexpr std::array<std::string_view, 5> keys{"from_m", "to_m", "patches", "first_m",
                                                        "last_m"};
  return keys;
}
inline std::span<const std::string_view> required_keys(const BlockSpec*) {
  static constexpr std::array<std::string_view, 2> keys{"x", "y"};
  return keys;
}

template <class S, class T>
concept Like = std::same_as<std::remove_const_t<S>, T>;

template <class V, Like<AxisPiece> S>
void visit_fields(V& v, S& a) {
  v("from_m", a.from_m, kCoordinate);
  v("to_m", a.to_m, kCoordinate);
  v("patches", a.patches, Int{1, 4096});
  v("first_m", a.first_m, Real{0.0, 2.0e3, false, false, "m (0: uniform)"});
  v("last_m", a.last_m, Real{0.0, 2.0e3, false, false, "m (0: uniform)"});
}

template <class V, Like<BlockSpec> S>
void visit_fields(V& v, S& b) {
  v("x", b.x, List<Fields>{1, 64, {}});
  v("y", b.y, List<Fields>{1, 64, {}});
  v("mapped", b.mapped, Flag{});
  v("corners", b.corners, kCoordinate);
  v("y_right", b.y_right, List<Fields>{0, 64, {}});
}

template <class V, Like<MeshSpec> S>
void visit_fields(V& v, S& m) {
  v("blocks", m.blocks, List<Fields>{1, 64, {}});
  v("refinements", m.refinements, Int{0, 4});
}

template <class V, Like<BodySpec> S>
void visit_fields(V& v, S& b) {
  v("center_m", b.center_m, kCoordinate);
  v("shape", b.shape, Choice{kBodyShapeNames});
  v("radius_m", b.radius_m, Real{0.0, 1.0e3, true, false, "m"});
  v("half_size_m", b.half_size_m, Real{0.0, 1.0e3, true, false, "m"});
  v("angle_rad", b.angle_rad, Real{-1.0e3, 1.0e3, false, false, "rad"});
  v("initial_velocity_mps", b.initial_velocity_mps, Real{-1.0e3, 1.0e3, false, false, "m/s"});
  v("solid", b.solid, Fields{});  // optional: absent, the scenario's solid
}

template <class V, Like<FluidSpec> S>
void visit_fields(V& v, S& f) {
  v("density_kgpm3", f.density_kgpm3, Real{0.0, 1.0e5, true, false, "kg/m^3"});
  v("viscosity_m2ps", f.viscosity_m2ps, Real{0.0, 1.0e3, true, false, "m^2/s"});
}

template <class V, Like<SolidSpec> S>
void visit_fields(V& v, S& s) {
  v("density_kgpm3", s.density_kgpm3, Real{0.0, 1.0e5, true, false, "kg/m^3"});
  v("mu_pa", s.mu_pa, Real{0.0, 1.0e12, true, false, "Pa"});
  v("lambda_pa", s.lambda_pa, Real{0.0, 1.0e12, false, false, "Pa"});
}

template <class V, Like<NumericsSpec> S>
void visit_fields(V& v, S& n) {
  v("time_step_s", n.time_step_s, Real{0.0, 1.0, true, false, "s"});
  v("end_time_s", n.end_time_s, Real{0.0, 1.0e6, true, false, "s"});
  v("time_step_max_doublings", n.time_step_max_doublings, Int{0, 6});
  v("time_step_wall_zone_m", n.time_step_wall_zone_m, Real{0.0, 1.0e3, false, false, "m"});
  v("time_step_patch_fraction", n.time_step_patch_fraction, Real{0.0, 1.0e3, true, false, "(of a patch side)"});
  v("time_step_wall_zone_doublings", n.time_step_wall_zone_doublings, Int{0, 6});
  v("time_error_tolerance_m", n.time_error_tolerance_m, Real{0.0, 1.0, false, false, "m per step (0: no error control)"});
  v("newton_budget", n.newton_budget, Int{1, 100});
  v("newton_rel_tol", n.newton_rel_tol, Real{0.0, 1.0, false, true});
  v("newton_abs_tol", n.newton_abs_tol, Real{0.0, 1.0});
  v("reuse_contraction", n.reuse_contraction, Real{0.0, 1.0});
  v("krylov_iterations", n.krylov_iterations, Int{0, 1000});
  v("assembly_threads", n.assembly_threads, Int{0, 64});
  v("failure_policy", n.failure_policy, Choice{kFailurePolicyNames});
  v("max_halvings", n.max_halvings, Int{0, 20});
  v("accept_flagged_reduction", n.accept_flagged_reduction, Real{0.0, 1.0, false, true});
  v("accept_flagged_max_residual", n.accept_flagged_max_residual, Real{0.0, 1.0e6});
  v("accept_best_max_residual", n.accept_best_max_residual, Real{0.0, 1.0e12, false, false, "(0: no bound)"});
  v("cip_gamma", n.cip_gamma, Real{0.0, 1.0e3});
  v("cip_transient_weight", n.cip_transient_weight, Real{0.0, 1.0e3});
  v("cip_wall_film_factor", n.cip_wall_film_factor, Real{0.0, 1.0e3});
  v("solid_alpha", n.solid_alpha, Real{0.0, 1.0e3});
  v("solid_s", n.solid_s, Real{0.0, 4.0});
  v("blend_eps_patches", n.blend_eps_patches, Real{0.0, 100.0, true, false, "patches"});
  v("blend_delta_patches", n.blend_delta_patches, Real{0.0, 100.0, true, false, "patches"});
  v("cut_snap", n.cut_snap, Real{0.0, 0.25});
  v("cut_snap_distance_m", n.cut_snap_distance_m, Real{0.0, 0.1, false, false, "m (0: off)"});
  v("cut_align_fraction", n.cut_align_fraction, Real{0.0, 0.5, false, false, "(0: off)"});
  v("identity_gap_m", n.identity_gap_m, Real{0.0, 1.0e3, false, false, "m (0: one patch)"});
  v("rereference_angle_rad", n.rereference_angle_rad, Real{0.0, 3.2, false, false, "rad (0: never)"});
  v("cavitation_pressure_pa", n.cavitation_pressure_pa,
    Real{-1.0e9, 0.0, false, false, "Pa (0: off)"});
  v("backflow_beta", n.backflow_beta, Real{0.0, 1.0, false, false, "(0: plain do-nothing)"});
}

template <class V, Like<ContactSpec> S>
void visit_fields(V& v, S& c) {
  v("gamma_c", c.gamma_c, Real{0.0, 1.0e9, false, false, "N/m (0: no contact force)"});
  v("dist0_m", c.dist0_m, Real{0.0, 1.0e3, false, false, "m"});
  v("min_dist_fraction", c.min_dist_fraction, Real{0.0, 1.0, true, false, "(fraction of dist0_m)"});
  v("corners_as_walls", c.corners_as_walls, Flag{});
  v("corner_barrier_speed_mps", c.corner_barrier_speed_mps, Real{0.0, 1.0e3, false, false, "m/s (0: no barrier)"});
  v("corner_barrier_reach_m", c.corner_barrier_reach_m, Real{0.0, 1.0, true, false, "m"});
}

template <class V, Like<OutputSpec> S>
void visit_fields(V& v, S& o) {
  v("frame_every", o.frame_every, Int{1, 1000000});
  v("width_px", o.width_px, Int{16, 7680});
  v("height_px", o.height_px, Int{16, 7680});
  v("fps", o.fps, Int{1, 240});
  v("field", o.field, Choice{kOutputFieldNames});
  v("mesh_overlay", o.mesh_overlay, Flag{});
  v("range_min", o.range_min, Real{-1.0e30, 1.0e30});
  v("range_max", o.range_max, Real{-1.0e30, 1.0e30});
}

/// The whole file. `source` is not part of it: it records where the file came from.
/// `method` comes first: the reader starts the numerics from its preset.
template <class V, Like<Scenario> S>
void visit_fields(V& v, S& s) {
  v("method", s.method, Choice{kMethodNames});
  v("name", s.name, Name{});
  v("mesh", s.mesh, Fields{});
  v("walls", s.walls, List<Real>{0, 1000, kCoordinate});
  v("body", s.body, Fields{});
  v("bodies", s.bodies, List<Fields>{0, kMaxBodies, {}});
  v("fluid", s.fluid, Fields{});
  v("solid", s.solid, Fields{});
  v("gravity_mps2", s.gravity_mps2, Real{-1.0e3, 1.0e3, false, false, "m/s^2"});
  v("buoyancy", s.buoyancy, Flag{});
  v("numerics", s.numerics, Fields{});
  v("contact", s.contact, Fields{});
  v("output", s.output, Fields{});
}

}  // namespace fsi::io
