#pragma once
/// \file step_policy.hpp
/// What Engine::step() does with one Newton attempt at a step: accept it, retry at half
/// the step, remember it as the best so far, or give up -- the failure policy of the
/// scenario (NumericsSpec::failure_policy) as one pure function, testable on its own.
///
/// One rule holds whatever the policy: an attempt whose Newton never took an iterate
/// (every line search failed, so x is still the initial guess) is no solution. Accepting
/// it would advance time with the body frozen where it was; a stairs run did exactly that
/// for 45 steps before this rule.
#include "fsi/scenario.hpp"
#include "solve/newton.hpp"

namespace fsi::core {

/// True if Newton converged or moved the iterate at least once.
inline bool made_progress(const solve::NewtonResult& r) { return r.converged || r.accepted_iterates > 0; }

enum class AttemptAction {
  accept,         ///< converged, or accepted and flagged by the policy
  retry_halved,   ///< try again with k/2
  accept_best,    ///< no more retries: accept the best attempt kept so far
  give_up         ///< reject the step (roll back)
};

struct AttemptVerdict {
  AttemptAction action = AttemptAction::give_up;
  /// halve_step: this attempt may be accepted later if no other does better.
  bool candidate = false;
  /// Accepted although unconverged because its residual got down to
  /// accept_flagged_reduction of its start and to accept_flagged_max_residual (the step
  /// report says so).
  bool flagged_early = false;
};

/// The verdict on attempt number `attempt_no` (0: the full step). `finite`: the result
/// has no NaN/Inf; `have_best`: an earlier attempt is kept as a candidate.
AttemptVerdict judge_attempt(const NumericsSpec& numerics, const solve::NewtonResult& r, bool finite,
                             int attempt_no, bool have_best);

}  // namespace fsi::core
