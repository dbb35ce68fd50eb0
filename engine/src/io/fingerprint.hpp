#pragma once
/// \file fingerprint.hpp
/// What the scenario fingerprint (fsi::fingerprint, scenario.hpp) covers, and the older
/// formula that checkpoint format 3 files carry.
#include <array>
#include <string>

#include "fsi/scenario.hpp"

namespace fsi::io {

/// Numerics keys that only steer the solver (how many Newton iterations, when to stop,
/// what to do on failure, how long the next step may be). They are not part of the
/// fingerprint since checkpoint format 4: the same state may go on with other solver
/// controls. (The failure policy halve_step already varies the step's length; the longer
/// steps away from the walls do the same.) The step limits are hashed as the lengths
/// time_step_max_s and time_step_wall_zone_max_s, the form format 3 had them in; their
/// keys time_step_max_doublings and time_step_wall_zone_doublings are listed too, for
/// the study scripts that read this list (tools/study-common.sh).
inline constexpr std::array<const char*, 18> kSolverControlKeys{
    "newton_budget",   "newton_rel_tol",        "newton_abs_tol",           "reuse_contraction",
    "failure_policy",  "max_halvings",          "accept_flagged_reduction", "accept_flagged_max_residual",
    "time_step_max_s", "time_step_wall_zone_m", "time_step_patch_fraction", "time_step_wall_zone_max_s",
    "accept_best_max_residual", "krylov_iterations", "assembly_threads",
    "time_error_tolerance_m", "time_step_max_doublings", "time_step_wall_zone_doublings"};

/// The fingerprint as checkpoint format 3 computed it (solver controls included); a
/// format 3 checkpoint loads when this matches.
std::string fingerprint_v3(const Scenario& scenario);

}  // namespace fsi::io
