#include "core/step_policy.hpp"

#include <limits>

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
  const double final_residual = r.norms.empty() ? std::numeric_limits<double>::infinity() : r.norms.back();
  if (usable && r.relative_residual <= numerics.accept_flagged_reduction &&
      final_residual <= numerics.accept_flagged_max_residual) {
    // Stalled just short of the tolerance: smaller steps would stall alike. (Far down
    // from a huge start is not short of the tolerance: that one is halved.)
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
