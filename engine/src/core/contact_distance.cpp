#include "core/contact_distance.hpp"

#include <algorithm>

#include "mesh/walls.hpp"

namespace fsi::core {

namespace {

/// The wall end points, each once (consecutive walls share theirs).
std::vector<Eigen::Vector2d> wall_end_points(const std::vector<Segment2>& walls) {
  std::vector<Eigen::Vector2d> points;
  for (const Segment2& w : walls)
    for (const Point2& p : {w.a, w.b}) {
      const Eigen::Vector2d q(p.x, p.y);
      if (std::none_of(points.begin(), points.end(), [&](const Eigen::Vector2d& o) { return (o - q).norm() <= 1e-12; }))
        points.push_back(q);
    }
  return points;
}

}  // namespace

double gap_to_interface(const Eigen::Vector2d& point, const std::vector<fe::InterfaceSegment>& interface, double cap_m) {
  double gap = cap_m;
  for (const fe::InterfaceSegment& seg : interface)
    gap = std::min(gap, mesh::distance_to_segment(Segment2{{seg.a.x(), seg.a.y()}, {seg.b.x(), seg.b.y()}}, point));
  return gap;
}

ContactDistance::ContactDistance(const std::vector<Segment2>& walls,
                                 const std::vector<fe::InterfaceSegment>& interface,
                                 const Eigen::Vector2d& body_centroid, double reach_m, double window_m,
                                 bool corners_as_walls)
    : walls_(walls), window_m_(window_m) {
  if (!corners_as_walls || interface.empty()) return;
  for (const Eigen::Vector2d& corner : wall_end_points(walls)) {
    const double gap = gap_to_interface(corner, interface, reach_m);
    const Eigen::Vector2d to_body = body_centroid - corner;
    if (gap >= reach_m || !(to_body.norm() > 0.0)) continue;
    corner_walls_.push_back({corner, to_body.normalized()});
  }
}

double ContactDistance::operator()(const Eigen::Vector2d& x) const {
  double d = mesh::distance_to_walls(walls_, x).distance_m;
  for (const CornerWall& c : corner_walls_) {
    if ((x - c.corner).norm() > window_m_) continue;
    d = std::min(d, std::max(0.0, (x - c.corner).dot(c.normal)));
  }
  return d;
}

}  // namespace fsi::core
