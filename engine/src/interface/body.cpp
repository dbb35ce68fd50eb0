#include "interface/body.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fsi/state.hpp"

namespace fsi::interface {

namespace {

/// The root s of (r0 z0 / (s + r0))^2 + (z1 / (s + 1))^2 = 1 by bisection (Eberly), where
/// z = y / e and r0 = (e0 / e1)^2; g is the value of the left side less 1 at s = 0.
double ellipse_root(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  double s0 = z1 - 1.0;
  double s1 = g < 0.0 ? 0.0 : std::hypot(n0, z1) - 1.0;
  double s = 0.0;
  for (int i = 0; i < 1100; ++i) {  // at most the doubles between s0 and s1
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1) break;
    const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1.0);
    const double value = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (value > 0.0) s0 = s;
    else if (value < 0.0) s1 = s;
    else break;
  }
  return s;
}

/// Distance from (y0, y1), both >= 0, to the ellipse with semi-axes e0 >= e1 > 0.
double ellipse_distance_first_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0, z1 = y1 / e1;
      const double g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0.0) return 0.0;
      const double r0 = (e0 / e1) * (e0 / e1);
      const double s = ellipse_root(r0, z0, z1, g);
      return std::hypot(r0 * y0 / (s + r0) - y0, y1 / (s + 1.0) - y1);
    }
    return std::abs(y1 - e1);
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    return std::hypot(e0 * xde0 - y0, e1 * std::sqrt(1.0 - xde0 * xde0));
  }
  return std::abs(y0 - e0);
}

}  // namespace

double shape_distance(const BodySpec& body, const Vec2& X) {
  // Into the body's own axes.
  const double c = std::cos(body.angle_rad), s = std::sin(body.angle_rad);
  const Vec2 d = X - Vec2(body.center_m.x, body.center_m.y);
  const Vec2 p(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const double a = body.half_size_m.x, b = body.half_size_m.y;
  switch (body.shape) {
    case BodyShape::circle:
      return p.norm() - body.radius_m;
    case BodyShape::ellipse: {
      const double y0 = std::abs(p.x()), y1 = std::abs(p.y());
      const bool inside = (y0 / a) * (y0 / a) + (y1 / b) * (y1 / b) < 1.0;
      // The bisection wants the major axis first.
      const double dist = a >= b ? ellipse_distance_first_quadrant(a, b, y0, y1)
                                 : ellipse_distance_first_quadrant(b, a, y1, y0);
      return inside ? -dist : dist;
    }
    case BodyShape::rounded_rectangle: {
      const double r = body.radius_m;
      const double qx = std::abs(p.x()) - (a - r), qy = std::abs(p.y()) - (b - r);
      return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - r;
    }
  }
  return p.norm() - body.radius_m;
}

Vec2 initial_fluid_velocity(const BodySpec& body, const Vec2& x) {
  const Vec2 u(body.initial_velocity_mps.x, body.initial_velocity_mps.y);
  const Vec2 d = x - Vec2(body.center_m.x, body.center_m.y);
  const double r2 = d.squaredNorm();
  if (u.isZero() || !(r2 > 0.0)) return Vec2::Zero();
  // The circle of the body's area (the ball itself: body_area / pi = r^2 up to rounding,
  // so the ball keeps its own radius).
  const double R2 = body.shape == BodyShape::circle ? body.radius_m * body.radius_m : fsi::body_area(body) / std::numbers::pi;
  const double s = R2 / r2;  // (R/r)^2
  const Vec2 e = d / std::sqrt(r2);
  return s * (2.0 * u.dot(e) * e - u);
}

double scene_distance(std::span<const BodySpec> bodies, const Vec2& X) {
  double d = initial_distance(bodies[0], X);
  for (std::size_t i = 1; i < bodies.size(); ++i) d = std::min(d, initial_distance(bodies[i], X));
  return d;
}

int nearest_body(std::span<const BodySpec> bodies, const Vec2& X, int ties) {
  int best = 0;
  double d = initial_distance(bodies[0], X);
  for (std::size_t i = 1; i < bodies.size(); ++i) {
    const double di = initial_distance(bodies[i], X);
    if (di < d) {
      d = di;
      best = static_cast<int>(i);
    }
  }
  if (ties >= 0) return best;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (static_cast<int>(i) != best && initial_distance(bodies[i], X) - d <= kTieDistance_m) return ties;
  return best;
}

Vec2 initial_fluid_velocity(std::span<const BodySpec> bodies, const Vec2& x) {
  Vec2 v = Vec2::Zero();
  for (const BodySpec& body : bodies) v += initial_fluid_velocity(body, x);
  return v;
}

fe::LevelSet ips_level_set(std::span<const BodySpec> bodies, const fe::CutMesh& cut,
                           const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution) {
  return [bodies, &cut, &buckets, &solution](const Vec2& x) {
    const fe::Location loc = fe::locate(cut, buckets, x, 1e-6);
    if (loc.element < 0) return scene_distance(bodies, x);
    const Vec2 u(fe::evaluate(cut, loc, solution, kFieldsPerNode, kUx),
                 fe::evaluate(cut, loc, solution, kFieldsPerNode, kUy));
    return scene_distance(bodies, x - u);
  };
}

std::vector<int> element_bodies(std::span<const BodySpec> bodies, const fe::CutMesh& next, const fe::CutMesh& cut,
                                const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution) {
  std::vector<int> body(next.elements.size(), -1);
  for (std::size_t k = 0; k < next.elements.size(); ++k) {
    const fe::SubElement& e = next.elements[k];
    if (e.phase != Phase::solid) continue;
    if (bodies.size() == 1) {
      body[k] = 0;
      continue;
    }
    Vec2 c = Vec2::Zero();
    for (int i = 0; i < e.vertices; ++i) c += next.x[e.node[i]];
    c /= e.vertices;
    const fe::Location loc = fe::locate(cut, buckets, c, 1e-6);
    const Vec2 u = loc.element < 0 ? Vec2::Zero()
                                   : Vec2(fe::evaluate(cut, loc, solution, kFieldsPerNode, kUx),
                                          fe::evaluate(cut, loc, solution, kFieldsPerNode, kUy));
    body[k] = nearest_body(bodies, c - u);
  }
  return body;
}

std::vector<int> segment_bodies(const fe::CutMesh& cut, const std::vector<int>& element_body) {
  std::vector<int> body(cut.interface.size(), 0);
  if (element_body.size() != cut.elements.size()) return body;
  for (std::size_t i = 0; i < cut.interface.size(); ++i)
    for (int k = cut.first_element[cut.interface[i].patch]; k < cut.first_element[cut.interface[i].patch + 1]; ++k)
      if (element_body[k] >= 0) {
        body[i] = element_body[k];
        break;
      }
  return body;
}

}  // namespace fsi::interface

namespace fsi {

double body_area(const BodySpec& body) {
  const double a = body.half_size_m.x, b = body.half_size_m.y, r = body.radius_m;
  switch (body.shape) {
    case BodyShape::circle: return std::numbers::pi * r * r;
    case BodyShape::ellipse: return std::numbers::pi * a * b;
    case BodyShape::rounded_rectangle: return 4.0 * a * b - (4.0 - std::numbers::pi) * r * r;
  }
  return std::numbers::pi * r * r;
}

std::span<const BodySpec> scene_bodies(const Scenario& scenario) {
  if (scenario.bodies.empty()) return {&scenario.body, 1};
  return scenario.bodies;
}

const SolidSpec& body_solid(const Scenario& scenario, const BodySpec& body) {
  return body.solid ? *body.solid : scenario.solid;
}

double body_reach(const BodySpec& body) {
  const double a = body.half_size_m.x, b = body.half_size_m.y, r = body.radius_m;
  switch (body.shape) {
    case BodyShape::circle: return r;
    case BodyShape::ellipse: return std::max(a, b);
    case BodyShape::rounded_rectangle: return std::hypot(a - r, b - r) + r;
  }
  return r;
}

}  // namespace fsi
