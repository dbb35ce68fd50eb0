#include "core/time_step_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::core {

double cut_patch_side(const mesh::PatchMesh& mesh, const fe::CutMesh& cut) {
  double side_m = std::numeric_limits<double>::infinity();
  for (int p = 0; p < mesh.num_patches(); ++p) {
    const mesh::Patch& patch = mesh.patches[p];
    bool at_interface = cut.kind[p] != fe::PatchKind::uncut;
    for (int c : mesh::kCornerLocal) at_interface = at_interface || cut.corner_sign[patch.node[c]] == 0;
    if (at_interface) side_m = std::min(side_m, patch.min_size_m);
  }
  return side_m;
}

SolidMotion solid_motion(const fe::CutMesh& cut, const Eigen::VectorXd& solution, const fe::CutMesh& previous_cut,
                         const Eigen::VectorXd& previous_solution, double last_step_s) {
  SolidMotion motion;
  const auto velocity = [](const Eigen::VectorXd& x, std::size_t node) {
    return Eigen::Vector2d(x[kFieldsPerNode * node + kVx], x[kFieldsPerNode * node + kVy]);
  };
  const std::size_t nodes = std::min(cut.touches_solid.size(), static_cast<std::size_t>(solution.size() / kFieldsPerNode));
  const bool previous_usable = last_step_s > 0.0 && previous_cut.touches_solid.size() == nodes &&
                               previous_solution.size() == solution.size();
  for (std::size_t node = 0; node < nodes; ++node) {
    if (!cut.touches_solid[node]) continue;
    const Eigen::Vector2d v = velocity(solution, node);
    motion.max_speed_mps = std::max(motion.max_speed_mps, v.norm());
    const bool inside_at_both = !cut.touches_fluid[node] && previous_usable && previous_cut.touches_solid[node] &&
                                !previous_cut.touches_fluid[node];
    if (inside_at_both)
      motion.max_acceleration_mps2 =
          std::max(motion.max_acceleration_mps2, (v - velocity(previous_solution, node)).norm() / last_step_s);
  }
  return motion;
}

double choose_time_step(const NumericsSpec& n, const Functionals& f, double cut_patch_side_m, double time_s,
                        double history_limit_s, const SolidMotion& motion) {
  const double k = n.time_step_s;
  // Error control may ask for less than k (an impact): the longest k 2^j, j >= -3, within it.
  if (n.time_error_tolerance_m > 0.0 && history_limit_s > 0.0 && history_limit_s < k * (1.0 - 1e-12)) {
    double shorter = 0.5 * k;
    while (shorter > history_limit_s * (1.0 + 1e-12) && shorter > 0.125 * k * (1.0 + 1e-12)) shorter *= 0.5;
    return shorter;
  }
  if (!(n.time_step_max_s() > k)) return k;  // off (0), or no longer step allowed
  const double history_s = history_limit_s > 0.0 ? history_limit_s : n.time_step_max_s();
  const double longest_s = std::min(n.time_step_max_s(), history_s);
  // In the wall zone only up to time_step_wall_zone_max_s() (0: k).
  double longest_in_zone_s = std::min(std::max(k, n.time_step_wall_zone_max_s()), longest_s);
  // With several bodies the gap between two of them counts as a wall's, and the fastest
  // body's speed as the scene's.
  double distance_m = f.min_distance_m;
  for (const Functionals::Body& b : f.bodies) distance_m = std::min(distance_m, b.min_body_distance_m);
  // In real contact (distance 0 with an interface) the wall itself is no distance away:
  // only a body at rest there takes longer steps, by the patch rule alone.
  const bool touching = distance_m > 0.0 && distance_m < kTouchingDistance_m;
  const bool real_contact = (!(distance_m > 0.0) || touching) && std::isfinite(cut_patch_side_m);
  if (touching) longest_in_zone_s = std::min(longest_in_zone_s, kTouchingStepFactor * k);
  const double gap_m = distance_m - n.time_step_wall_zone_m;
  double speed_mps = std::hypot(f.mean_vx_mps, f.mean_vy_mps);
  for (const Functionals::Body& b : f.bodies) speed_mps = std::max(speed_mps, std::hypot(b.mean_vx_mps, b.mean_vy_mps));
  // In the zone: what the solid's nodes reach soon, not only the mean (see
  // kWallZoneLookahead_s).
  const double nodes_soon_mps = motion.max_speed_mps + motion.max_acceleration_mps2 * kWallZoneLookahead_s;
  if (!std::isfinite(speed_mps) || !std::isfinite(nodes_soon_mps) || !std::isfinite(distance_m)) return k;
  const double zone_speed_mps = std::max(speed_mps, nodes_soon_mps);
  // A longer step must not overshoot the end (t accumulates rounding: a little slack).
  const double time_left_s = n.end_time_s - time_s + 1e-6 * k;
  double chosen = k;
  for (double longer = 2.0 * k; longer <= longest_s * (1.0 + 1e-12); longer *= 2.0) {
    // Outside the zone: at least kStepsToWallZone such steps to reach it. Inside (or
    // about to enter): as many to reach the wall itself.
    const bool outside_zone_ok = gap_m > 0.0 && kStepsToWallZone * speed_mps * longer <= gap_m;
    const bool in_zone_ok = longer <= longest_in_zone_s * (1.0 + 1e-12) &&
                            ((distance_m > 0.0 && kStepsToWallZone * zone_speed_mps * longer <= distance_m) ||
                             real_contact) &&
                            zone_speed_mps * longer <=
                                kWallZonePatchFraction * n.time_step_patch_fraction * cut_patch_side_m;
    if (!(outside_zone_ok || in_zone_ok) || longer > time_left_s) break;
    if (speed_mps * longer > n.time_step_patch_fraction * cut_patch_side_m) break;
    chosen = longer;
  }
  return chosen;
}

double next_time_step_limit(const StepOutcome& outcome, double base_step_s) {
  if (!outcome.calm) return base_step_s;
  if (outcome.newton_iterations > kCalmNewtonIterations) return std::max(base_step_s, 0.5 * outcome.time_step_s);
  return std::max(base_step_s, 2.0 * outcome.time_step_s);
}

}  // namespace fsi::core
