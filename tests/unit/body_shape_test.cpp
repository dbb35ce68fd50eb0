// The initial shapes (interface/body.hpp): d0 is the signed distance to the ellipse and
// the rounded rectangle (checked against the nearest of many boundary points), turned by
// angle_rad about the centre, and their areas and reach.
#include "interface/body.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using fsi::mesh::Vec2;

/// Boundary points of `body` in its own axes, about `count` of them, by the shape's
/// parametrization (the ellipse by its angle, the rounded rectangle by its four sides and
/// four quarter circles).
std::vector<Vec2> boundary(const fsi::BodySpec& body, int count) {
  std::vector<Vec2> points;
  const double a = body.half_size_m.x, b = body.half_size_m.y, r = body.radius_m;
  if (body.shape == fsi::BodyShape::ellipse) {
    for (int i = 0; i < count; ++i) {
      const double t = 2.0 * std::numbers::pi * i / count;
      points.emplace_back(a * std::cos(t), b * std::sin(t));
    }
    return points;
  }
  const int per = count / 8;
  for (int i = 0; i <= per; ++i) {
    const double s = static_cast<double>(i) / per;
    for (double sign : {-1.0, 1.0}) {
      points.emplace_back(-(a - r) + 2.0 * (a - r) * s, sign * b);
      points.emplace_back(sign * a, -(b - r) + 2.0 * (b - r) * s);
    }
    const double t = 0.5 * std::numbers::pi * s;
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0})
        points.emplace_back(sx * (a - r + r * std::cos(t)), sy * (b - r + r * std::sin(t)));
  }
  return points;
}

/// d0 by the nearest boundary point, signed by the shape's own inside test.
double brute_distance(const Vec2& p_body, const std::vector<Vec2>& points, bool inside) {
  double best = INFINITY;
  for (const Vec2& q : points) best = std::min(best, (q - p_body).norm());
  return inside ? -best : best;
}

bool inside_own_axes(const fsi::BodySpec& body, const Vec2& p) {
  const double a = body.half_size_m.x, b = body.half_size_m.y, r = body.radius_m;
  if (body.shape == fsi::BodyShape::ellipse) return (p.x() / a) * (p.x() / a) + (p.y() / b) * (p.y() / b) < 1.0;
  const double qx = std::abs(p.x()) - (a - r), qy = std::abs(p.y()) - (b - r);
  if (qx <= 0.0 || qy <= 0.0) return std::abs(p.x()) < a && std::abs(p.y()) < b;
  return std::hypot(qx, qy) < r;
}

void expect_signed_distance(const fsi::BodySpec& body) {
  const std::vector<Vec2> points = boundary(body, 150000);
  const double c = std::cos(body.angle_rad), s = std::sin(body.angle_rad);
  int checked = 0;
  for (double x = -0.8; x <= 0.8; x += 0.0731)
    for (double y = -0.7; y <= 0.7; y += 0.0677) {
      const Vec2 p_body(x, y);  // in the body's axes; in the plane turned and moved
      const Vec2 X(body.center_m.x + c * x - s * y, body.center_m.y + s * x + c * y);
      const double expected = brute_distance(p_body, points, inside_own_axes(body, p_body));
      EXPECT_NEAR(fsi::interface::initial_distance(body, X), expected, 2e-5) << "at (" << x << ", " << y << ")";
      ++checked;
    }
  EXPECT_GT(checked, 300);
}

TEST(BodyShape, EllipseIsItsSignedDistanceTurnedAndMoved) {
  fsi::BodySpec body;
  body.shape = fsi::BodyShape::ellipse;
  body.center_m = {0.3, -0.2};
  body.half_size_m = {0.45, 0.25};
  body.angle_rad = 0.4;
  expect_signed_distance(body);
  body.half_size_m = {0.2, 0.5};  // the major axis along the body's y
  expect_signed_distance(body);
  // On the axes, where the bisection has its special cases.
  body.angle_rad = 0.0;
  body.center_m = {0.0, 0.0};
  EXPECT_NEAR(fsi::interface::initial_distance(body, {0.0, 0.0}), -0.2, 1e-15);
  EXPECT_NEAR(fsi::interface::initial_distance(body, {0.0, 0.7}), 0.2, 1e-15);
  EXPECT_NEAR(fsi::interface::initial_distance(body, {0.3, 0.0}), 0.1, 1e-15);
}

TEST(BodyShape, RoundedRectangleIsItsSignedDistanceTurnedAndMoved) {
  fsi::BodySpec body;
  body.shape = fsi::BodyShape::rounded_rectangle;
  body.center_m = {-0.1, 0.25};
  body.half_size_m = {0.4, 0.25};
  body.radius_m = 0.1;
  body.angle_rad = -0.3;
  expect_signed_distance(body);
}

TEST(BodyShape, AreaAndReach) {
  fsi::BodySpec ball;
  EXPECT_DOUBLE_EQ(fsi::body_area(ball), std::numbers::pi * 0.16);
  EXPECT_EQ(fsi::body_reach(ball), 0.4);
  fsi::BodySpec e = ball;
  e.shape = fsi::BodyShape::ellipse;
  e.half_size_m = {0.45, 0.3};
  EXPECT_DOUBLE_EQ(fsi::body_area(e), std::numbers::pi * 0.45 * 0.3);
  EXPECT_EQ(fsi::body_reach(e), 0.45);
  fsi::BodySpec r = ball;
  r.shape = fsi::BodyShape::rounded_rectangle;
  r.half_size_m = {0.4, 0.25};
  r.radius_m = 0.1;
  // The rectangle less four corner squares plus four quarter circles; counted on a grid.
  int in = 0, all = 0;
  for (double x = -0.5; x < 0.5; x += 0.001)
    for (double y = -0.5; y < 0.5; y += 0.001, ++all) in += fsi::interface::initial_distance(r, {x, y}) < 0.0;
  EXPECT_NEAR(fsi::body_area(r), 4.0 * 0.4 * 0.25 - (4.0 - std::numbers::pi) * 0.01, 1e-15);
  EXPECT_NEAR(in * 1e-6, fsi::body_area(r), 2e-3);
  EXPECT_NEAR(fsi::body_reach(r), std::hypot(0.3, 0.15) + 0.1, 1e-15);
}

}  // namespace
