#include "core/time_error_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fsi/state.hpp"

namespace fsi::core {

namespace {

/// Inside the solid at a level: touches the solid and not the fluid (an interface node's
/// value belongs to another material point from level to level).
bool inside(const fe::CutMesh& cut, std::size_t node) {
  return cut.touches_solid[node] && !cut.touches_fluid[node];
}

}  // namespace

double displacement_error_estimate(const fe::CutMesh& previous_cut, const Eigen::VectorXd& previous,
                                   const fe::CutMesh& current_cut, const Eigen::VectorXd& current,
                                   const fe::CutMesh& next_cut, const Eigen::VectorXd& next, double previous_k_s,
                                   double k_s, const std::vector<int>& node_body) {
  const std::size_t nodes = static_cast<std::size_t>(next.size() / kFieldsPerNode);
  if (!(previous_k_s > 0.0) || !(k_s > 0.0) || previous.size() != next.size() || current.size() != next.size() ||
      previous_cut.touches_solid.size() != nodes || current_cut.touches_solid.size() != nodes ||
      next_cut.touches_solid.size() != nodes)
    return -1.0;
  const auto displacement = [](const Eigen::VectorXd& x, std::size_t node) {
    return Eigen::Vector2d(x[kFieldsPerNode * node + kUx], x[kFieldsPerNode * node + kUy]);
  };
  const bool per_body = node_body.size() == nodes;
  int bodies = 1;
  if (per_body)
    for (int b : node_body) bodies = std::max(bodies, b + 1);
  struct Sums {
    Eigen::Vector2d prev = Eigen::Vector2d::Zero(), cur = Eigen::Vector2d::Zero(), next = Eigen::Vector2d::Zero();
    std::size_t count = 0;
  };
  std::vector<Sums> sums(static_cast<std::size_t>(bodies));
  for (std::size_t node = 0; node < nodes; ++node) {
    if (!inside(previous_cut, node) || !inside(current_cut, node) || !inside(next_cut, node)) continue;
    const int b = per_body ? node_body[node] : 0;
    if (b < 0) continue;
    Sums& s = sums[static_cast<std::size_t>(b)];
    s.prev += displacement(previous, node);
    s.cur += displacement(current, node);
    s.next += displacement(next, node);
    ++s.count;
  }
  double e = -1.0;
  for (const Sums& s : sums) {
    if (s.count == 0) continue;
    const double n = static_cast<double>(s.count);
    const Eigen::Vector2d d_new = (s.next - s.cur) / n, d_last = (s.cur - s.prev) / n;
    e = std::max(e, k_s / (k_s + previous_k_s) * (d_new - (k_s / previous_k_s) * d_last).norm());
  }
  return std::isfinite(e) ? e : -1.0;
}

double step_for_error(double k_s, double error_m, double tolerance_m) {
  if (!(error_m >= 0.0) || !(tolerance_m > 0.0)) return std::numeric_limits<double>::infinity();
  if (error_m == 0.0) return 2.0 * k_s;
  return k_s * std::clamp(0.8 * std::sqrt(tolerance_m / error_m), 0.25, 2.0);
}

}  // namespace fsi::core
