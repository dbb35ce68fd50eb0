#pragma once
/// \file degeneration.hpp
/// Whether a step just solved left a body that no longer represents the scenario: a solid
/// turned inside out, a jump of the mass error, or an interface that jumped further than
/// the body can move in one step. Such a state is not kept (Engine::step() rolls it back
/// or retries the step shorter) so that a run stops with a report naming the step, the
/// cause and the place, rather than going on from a broken state -- a step that Newton
/// "converged" on a sliver can still do that, and an unconverged one accepted by the
/// failure policy often does.
#include <optional>
#include <string>
#include <vector>

#include "fe/cut_mesh.hpp"
#include "fsi/state.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::core {

/// The mass error may change by at most this much in one step, or by the area of the
/// largest patch the interface cuts relative to the body's, whichever is larger: a cut
/// rebuilt within one patch can add or drop up to that patch's area (a ball of R = 0.1 m
/// in 5 cm patches: 0.08; a sound campaign ball of R = 0.104 m on the stairs' mesh went
/// from 0.057 to 0.080 in one converged step). Example 1's steps change it by at most
/// 4e-4, in real contact (0 to 4.94 s with the default numerics); a rho_f = 100 stairs
/// body that accepted unconverged steps had a mass error of 4 two steps later
/// (NumericsSpec::accept_best_max_residual).
inline constexpr double kMassErrorJump = 0.02;

/// The interface may move by at most this many patch sides more than the body's speed
/// explains (2 |v| k, v the larger mean solid velocity of the two levels): the cut
/// snaps to nodes and moves nodes within a patch, so a sound step can move the discrete
/// interface by about one side beyond the motion itself.
inline constexpr double kInterfaceJumpPatchSides = 2.0;

/// What was found; `where_m` is the place (the body's centroid for the whole-body causes,
/// the first inverted point for an inversion).
struct Degeneration {
  std::string cause;
  Point2 where_m;
  /// The body reached the domain's open boundary: the solution may be sound, but the
  /// domain cannot hold the body any further, and no shorter step changes that.
  bool outside_domain = false;
};

/// The checks on the body after a step of `time_step_s` from `before` to `after`.
/// `inverted_points`: solid quadrature points with det(I - grad u) <= 0 in the new state,
/// `inverted_where_m` the first of them; `patch_side_m`: the largest patch side the
/// interface cuts (the scale of the discrete interface's own jitter); `patch_area_m2`: the
/// largest area of a patch it cuts (the mass error's; 0: kMassErrorJump alone).
std::optional<Degeneration> detect_degeneration(const Functionals& before, const Functionals& after,
                                                double time_step_s, double patch_side_m, int inverted_points,
                                                Point2 inverted_where_m, double patch_area_m2 = 0.0);

/// Several bodies: whether two of them touch in `cut` (element_body its sub-elements'
/// bodies, interface::element_bodies): a node shared by the solids of two bodies. The
/// level set of the scene cannot keep two touching bodies apart (one solid region), so
/// such a state is not kept; the message names both bodies.
std::optional<Degeneration> merged_bodies(const fe::CutMesh& cut, const std::vector<int>& element_body);

/// Whether the solid reaches the domain's open boundary in `cut`: a node of the boundary
/// that lies on no wall and belongs to a solid sub-element. The domain ends there; a body
/// that goes on through it loses what lies outside (Example 1's floor-only domain, a ball
/// of R = 0.43 m rolling out through the open left side: its mass error grew from 4e-3 to
/// 0.5 over 1.2 s before the mass-error check stopped the run). `where_m` is the first such
/// node; the message says what to change in the scenario.
std::optional<Degeneration> body_at_open_boundary(const mesh::PatchMesh& mesh, const fe::CutMesh& cut);

/// The largest side h_P of the patches the interface cuts (or passes through a corner of)
/// in `before` or `after`, and the largest area of such a patch; 0 without an interface.
struct CutPatchScale {
  double side_m = 0.0;
  double area_m2 = 0.0;
};
CutPatchScale largest_cut_patch(const mesh::PatchMesh& mesh, const fe::CutMesh& before, const fe::CutMesh& after);

}  // namespace fsi::core
