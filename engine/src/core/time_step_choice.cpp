#include "core/time_step_choice.hpp"

#include <cmath>

namespace fsi::core {

double choose_time_step(const NumericsSpec& n, const Functionals& f, double time_s) {
  const double k = n.time_step_s;
  if (!(n.time_step_max_s > k)) return k;  // off (0), or no longer step allowed
  const double gap_m = f.min_distance_m - n.time_step_wall_zone_m;
  if (!(gap_m > 0.0)) return k;
  const double speed_mps = std::hypot(f.mean_vx_mps, f.mean_vy_mps);
  if (!std::isfinite(speed_mps)) return k;
  // A longer step must not overshoot the end (t accumulates rounding: a little slack).
  const double time_left_s = n.end_time_s - time_s + 1e-6 * k;
  double chosen = k;
  for (double longer = 2.0 * k; longer <= n.time_step_max_s * (1.0 + 1e-12); longer *= 2.0) {
    if (kStepsToWallZone * speed_mps * longer > gap_m || longer > time_left_s) break;
    chosen = longer;
  }
  return chosen;
}

}  // namespace fsi::core
