#include "mesh/walls.hpp"

#include <algorithm>
#include <limits>

namespace fsi::mesh {

Eigen::Vector2d nearest_on_segment(const Segment2& segment, const Eigen::Vector2d& x) {
  const Eigen::Vector2d a(segment.a.x, segment.a.y), b(segment.b.x, segment.b.y);
  const Eigen::Vector2d d = b - a;
  const double len2 = d.squaredNorm();
  // A degenerate segment is its end point (validation rejects them, but stay defined).
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

double distance_to_segment(const Segment2& segment, const Eigen::Vector2d& x) {
  return (nearest_on_segment(segment, x) - x).norm();
}

WallDistance distance_to_walls(const std::vector<Segment2>& walls, const Eigen::Vector2d& x) {
  WallDistance best{std::numeric_limits<double>::infinity()};
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Eigen::Vector2d p = nearest_on_segment(walls[w], x);
    const double dist = (p - x).norm();
    if (dist < best.distance_m) best = {dist, static_cast<int>(w), p};
  }
  return best;
}

}  // namespace fsi::mesh
