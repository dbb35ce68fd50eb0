#include "core/corner_barrier.hpp"

#include <algorithm>
#include <cmath>


namespace fsi::core {

std::vector<Eigen::Vector2d> convex_corners(const std::vector<Segment2>& walls, const Eigen::Vector2d& body_centroid) {
  std::vector<Eigen::Vector2d> corners;
  const auto point = [](const Point2& p) { return Eigen::Vector2d(p.x, p.y); };
  for (std::size_t i = 0; i < walls.size(); ++i)
    for (std::size_t j = i + 1; j < walls.size(); ++j)
      for (int end_i = 0; end_i < 2; ++end_i)
        for (int end_j = 0; end_j < 2; ++end_j) {
          const Eigen::Vector2d corner = point(end_i == 0 ? walls[i].a : walls[i].b);
          if ((corner - point(end_j == 0 ? walls[j].a : walls[j].b)).norm() > 1e-12) continue;
          // Along each wall away from the corner; their bisector points into the wedge
          // between them. A convex corner has the body outside that wedge.
          const Eigen::Vector2d along_i = point(end_i == 0 ? walls[i].b : walls[i].a) - corner;
          const Eigen::Vector2d along_j = point(end_j == 0 ? walls[j].b : walls[j].a) - corner;
          if (!(along_i.norm() > 0.0 && along_j.norm() > 0.0)) continue;
          const Eigen::Vector2d bisector = along_i.normalized() + along_j.normalized();
          if (bisector.norm() < 1e-9) continue;  // collinear: no corner
          if ((body_centroid - corner).dot(bisector) >= 0.0) continue;
          if (std::none_of(corners.begin(), corners.end(), [&](const Eigen::Vector2d& c) { return (c - corner).norm() <= 1e-12; }))
            corners.push_back(corner);
        }
  return corners;
}

CornerBarrier::CornerBarrier(const std::vector<Segment2>& walls, const std::vector<fe::InterfaceSegment>& interface,
                             const Eigen::Vector2d& body_centroid, double reach_m, double window_m, double gamma,
                             double min_dist_fraction)
    : reach_m_(reach_m), window_m_(window_m), gamma_(gamma), min_dist_m_(min_dist_fraction * reach_m) {
  if (!(reach_m > 0.0 && gamma > 0.0) || interface.empty()) return;
  for (const Eigen::Vector2d& corner : convex_corners(walls, body_centroid))
    if (const std::optional<CornerLine> line = CornerLine::within_reach(corner, interface, body_centroid, reach_m))
      corners_.push_back(*line);
}

double CornerBarrier::pressure_pa(const Eigen::Vector2d& x) const {
  double p = 0.0;
  for (const CornerLine& line : corners_) {
    const double d = line.distance_m(x, window_m_);
    if (d < reach_m_) p = std::max(p, gamma_ * (reach_m_ - d) / std::max(d, min_dist_m_));
  }
  return p;
}

double CornerBarrier::gamma_for(double mass_kg_per_m, double speed_mps, double radius_m, double reach_m) {
  // Work of the pressure of unit gamma on a circle of radius R whose gap to a flat wall
  // closes from reach to 0, with the gap growing as d + s^2/(2R) along the interface and
  // the pressure bounded at d = 0.1 reach: 1.84 reach sqrt(2 R reach) [m^2] (by quadrature;
  // tests/unit/corner_barrier_test.cpp integrates it again).
  const double work_per_gamma = 1.84 * reach_m * std::sqrt(2.0 * radius_m * reach_m);
  if (!(work_per_gamma > 0.0)) return 0.0;
  return 2.0 * 0.5 * mass_kg_per_m * speed_mps * speed_mps / work_per_gamma;
}

double CornerBarrier::reach_for(double mass_kg_per_m, double speed_mps, double radius_m, double min_reach_m,
                                double mu_pa) {
  const double gamma = gamma_for(mass_kg_per_m, speed_mps, radius_m, min_reach_m);
  if (!(mu_pa > 0.0) || !(gamma > mu_pa)) return min_reach_m;
  return min_reach_m * std::cbrt((gamma / mu_pa) * (gamma / mu_pa));
}

double corner_barrier_reach_m(const Scenario& scenario, const BodySpec& body) {
  const SolidSpec& solid = body_solid(scenario, body);
  return CornerBarrier::reach_for(solid.density_kgpm3 * body_area(body), scenario.contact.corner_barrier_speed_mps,
                                  body_reach(body), scenario.contact.corner_barrier_reach_m, solid.mu_pa);
}

}  // namespace fsi::core
