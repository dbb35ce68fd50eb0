#include "core/contact_distance.hpp"

#include <algorithm>
#include <limits>

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

std::optional<CornerLine> CornerLine::within_reach(const Eigen::Vector2d& corner,
                                                   const std::vector<fe::InterfaceSegment>& interface,
                                                   const Eigen::Vector2d& body_centroid, double reach_m) {
  const Eigen::Vector2d to_body = body_centroid - corner;
  if (!(to_body.norm() > 0.0)) return std::nullopt;
  for (const fe::InterfaceSegment& seg : interface)
    if (mesh::distance_to_segment(Segment2{{seg.a.x(), seg.a.y()}, {seg.b.x(), seg.b.y()}}, corner) < reach_m)
      return CornerLine{corner, to_body.normalized()};
  return std::nullopt;
}

double CornerLine::distance_m(const Eigen::Vector2d& x, double window_m) const {
  if ((x - corner).norm() > window_m) return std::numeric_limits<double>::infinity();
  return std::max(0.0, (x - corner).dot(normal));
}

ContactDistance::ContactDistance(const std::vector<Segment2>& walls,
                                 const std::vector<fe::InterfaceSegment>& interface,
                                 const Eigen::Vector2d& body_centroid, double reach_m, double window_m,
                                 bool corners_as_walls)
    : walls_(walls), window_m_(window_m) {
  if (!corners_as_walls || interface.empty()) return;
  for (const Eigen::Vector2d& corner : wall_end_points(walls)) {
    if (const std::optional<CornerLine> line = CornerLine::within_reach(corner, interface, body_centroid, reach_m))
      corner_walls_.push_back(*line);
  }
}

double ContactDistance::operator()(const Eigen::Vector2d& x) const {
  double d = mesh::distance_to_walls(walls_, x).distance_m;
  for (const CornerLine& line : corner_walls_) d = std::min(d, line.distance_m(x, window_m_));
  return d;
}

}  // namespace fsi::core
