#include "triangle_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fsi::app {
namespace {

double angle_at(const Point2& at, const Point2& b, const Point2& c) {
  const double ux = b.x - at.x, uy = b.y - at.y, vx = c.x - at.x, vy = c.y - at.y;
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

}  // namespace

TriangleQuality measure_triangles(const FieldView& view) {
  TriangleQuality q;
  q.smallest_area_m2 = std::numeric_limits<double>::infinity();
  for (const auto& t : view.triangles) {
    const Point2& a = view.nodes[t[0]];
    const Point2& b = view.nodes[t[1]];
    const Point2& c = view.nodes[t[2]];
    const double largest =
        std::max({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)}) * 180.0 / std::numbers::pi;
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    const Point2 centroid{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    ++q.triangles;
    q.max_angle_above_150_deg += largest > 150.0;
    q.max_angle_above_160_deg += largest > 160.0;
    q.max_angle_above_170_deg += largest > 170.0;
    if (largest > q.worst_max_angle_deg) {
      q.worst_max_angle_deg = largest;
      q.worst_at = centroid;
    }
    if (area < q.smallest_area_m2) {
      q.smallest_area_m2 = area;
      q.smallest_at = centroid;
    }
  }
  if (q.triangles == 0) q.smallest_area_m2 = 0.0;
  return q;
}

}  // namespace fsi::app
