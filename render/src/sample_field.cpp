#include "fsi/sample_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <utility>

namespace fsi::render {
namespace {

constexpr double x_min = -1.0, x_max = 1.0, y_min = -1.0, y_max = 0.5;

// Grading maps [0, 1] onto itself: y clustered towards the bottom (the contact gap),
// x towards the middle. Both stay monotone, so the grid never folds.
double grade_y(double s) { return s * s * (1.5 - 0.5 * s); }
double grade_x(double s) { return s - 0.12 * std::sin(2 * std::numbers::pi * s); }

}  // namespace

FieldView sample_field_view(const SampleFieldOptions& o) {
  if (o.nx < 2 || o.ny < 2 || o.interface_segments < 3 || !(o.radius > 0)) {
    throw std::invalid_argument("SampleFieldOptions: need nx, ny >= 2, >= 3 segments, radius > 0");
  }
  FieldView v;
  v.time_s = o.time_s;
  v.step = 0;
  v.domain_min = {x_min, y_min};
  v.domain_max = {x_max, y_max};
  for (int j = 0; j < o.ny; ++j) {
    for (int i = 0; i < o.nx; ++i) {
      double sx = double(i) / (o.nx - 1), sy = double(j) / (o.ny - 1);
      if (o.graded) sx = grade_x(sx), sy = grade_y(sy);
      v.nodes.push_back({x_min + sx * (x_max - x_min), y_min + sy * (y_max - y_min)});
    }
  }
  const double r2 = o.radius * o.radius;
  std::set<std::pair<int, int>> edges;
  auto edge = [&edges](int a, int b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  for (int j = 0; j + 1 < o.ny; ++j) {
    for (int i = 0; i + 1 < o.nx; ++i) {
      const int a = j * o.nx + i, b = a + 1, c = a + o.nx + 1, d = a + o.nx;
      // Alternate the diagonal so the triangulation has no preferred direction.
      const bool flip = (i + j) % 2 == 1;
      const std::array<int, 3> t1 = flip ? std::array{a, b, d} : std::array{a, b, c};
      const std::array<int, 3> t2 = flip ? std::array{b, c, d} : std::array{a, c, d};
      for (const auto& t : {t1, t2}) {
        v.triangles.push_back(t);
        const Point2 m{(v.nodes[t[0]].x + v.nodes[t[1]].x + v.nodes[t[2]].x) / 3,
                       (v.nodes[t[0]].y + v.nodes[t[1]].y + v.nodes[t[2]].y) / 3};
        const double dx = m.x - o.ball_x, dy = m.y - o.ball_y;
        v.triangle_phase.push_back(dx * dx + dy * dy < r2 ? Phase::solid : Phase::fluid);
        edge(t[0], t[1]);
        edge(t[1], t[2]);
        edge(t[2], t[0]);
      }
    }
  }
  for (const auto& [a, b] : edges) v.mesh_edges.push_back({a, b});

  // The ball moves with velocity U = (0, -speed). Outside, the potential flow of a
  // moving cylinder: phi = -(R^2 / r^2) U.x', v = grad phi, a dipole decaying as 1/r^2.
  const double uy_ball = -o.speed;
  for (const Point2& p : v.nodes) {
    const double dx = p.x - o.ball_x, dy = p.y - o.ball_y, rr = dx * dx + dy * dy;
    double vx, vy, pr, ux, uy;
    if (rr < r2) {
      vx = 0.0;
      vy = uy_ball;
      pr = 400.0 * (-dy / o.radius);    // linear inside, matching the dipole at r = R
      ux = 0.04 * dx, uy = -0.06 * dy;  // squashed vertically
    } else {
      const double k = r2 / rr;  // R^2 / r^2
      // grad of -(k)(U.x') with U.x' = uy_ball * dy
      const double udotx = uy_ball * dy;
      vx = -(k * 0.0 - 2.0 * k / rr * dx * udotx);
      vy = -(k * uy_ball - 2.0 * k / rr * dy * udotx);
      pr = 400.0 * (-dy / o.radius) * k;
      ux = 0.04 * dx * k, uy = -0.06 * dy * k;
    }
    v.vx.push_back(vx);
    v.vy.push_back(vy);
    v.p.push_back(pr);
    v.ux.push_back(ux);
    v.uy.push_back(uy);
  }
  for (int k = 0; k < o.interface_segments; ++k) {
    const double a0 = 2 * std::numbers::pi * k / o.interface_segments;
    const double a1 = 2 * std::numbers::pi * (k + 1) / o.interface_segments;
    v.interface.push_back(
        {{o.ball_x + o.radius * std::cos(a0), o.ball_y + o.radius * std::sin(a0)},
         {o.ball_x + o.radius * std::cos(a1), o.ball_y + o.radius * std::sin(a1)}});
  }
  v.walls = {{{x_min, y_min}, {x_max, y_min}},
             {{x_max, y_min}, {x_max, y_max}},
             {{x_min, y_max}, {x_min, y_min}}};  // open at the top
  return v;
}

}  // namespace fsi::render
