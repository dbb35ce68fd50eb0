#include "core/step_policy.hpp"

namespace fsi::core {

AttemptVerdict judge_attempt(const NumericsSpec& numerics, const solve::NewtonResult& r, bool finite,
                             int attempt_no, bool have_best) {
  AttemptVerdict v;
  if (r.converged && finite) {
    v.action = AttemptAction::accept;
    return v;
  }
  const bool usable = finite && made_progress(r);
  switch (numerics.failure_policy) {
    case FailurePolicy::accept_and_flag:
      v.action = usable ? AttemptAction::accept : AttemptAction::give_up;
      return v;
    case FailurePolicy::stop_and_rollback:
      v.action = AttemptAction::give_up;
      return v;
    case FailurePolicy::halve_step:
      break;
  }
  if (usable && r.relative_residual <= numerics.accept_flagged_reduction) {
    // Stalled just short of the tolerance: smaller steps would stall alike.
    v.action = AttemptAction::accept;
    v.flagged_early = true;
    return v;
  }
  v.candidate = usable;
  if (attempt_no < numerics.max_halvings)
    v.action = AttemptAction::retry_halved;
  else
    v.action = (usable || have_best) ? AttemptAction::accept_best : AttemptAction::give_up;
  return v;
}

}  // namespace fsi::core
