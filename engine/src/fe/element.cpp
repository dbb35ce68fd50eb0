#include "fe/element.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::fe {

ShapeValues shape_at_reference(const CutMesh& cut, const SubElement& e, double xi, double eta) {
  ShapeValues s;
  s.n = e.vertices;
  const Vec2& x0 = cut.x[e.node[0]];
  const Vec2& x1 = cut.x[e.node[1]];
  const Vec2& x2 = cut.x[e.node[2]];
  if (e.vertices == 3) {
    s.value = {1.0 - xi - eta, xi, eta, 0.0};
    // J = [x1 - x0, x2 - x0]; grad N = J^{-T} grad_ref N.
    const Vec2 a = x1 - x0, b = x2 - x0;
    const double det = a.x() * b.y() - a.y() * b.x();
    const Vec2 g1(b.y() / det, -b.x() / det);   // grad xi
    const Vec2 g2(-a.y() / det, a.x() / det);   // grad eta
    s.grad = {-g1 - g2, g1, g2, Vec2::Zero()};
    return s;
  }
  const Vec2& x3 = cut.x[e.node[3]];
  s.value = {(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta};
  const std::array<double, 4> dxi{-(1 - eta), 1 - eta, eta, -eta};
  const std::array<double, 4> deta{-(1 - xi), -xi, xi, 1 - xi};
  const std::array<const Vec2*, 4> xs{&x0, &x1, &x2, &x3};
  Vec2 t_xi = Vec2::Zero(), t_eta = Vec2::Zero();
  for (int i = 0; i < 4; ++i) {
    t_xi += dxi[i] * *xs[i];
    t_eta += deta[i] * *xs[i];
  }
  const double det = t_xi.x() * t_eta.y() - t_xi.y() * t_eta.x();
  for (int i = 0; i < 4; ++i) {
    // [dN/dx, dN/dy] = J^{-T} [dN/dxi, dN/deta], J = [t_xi t_eta].
    s.grad[i] = Vec2((t_eta.y() * dxi[i] - t_xi.y() * deta[i]) / det,
                     (-t_eta.x() * dxi[i] + t_xi.x() * deta[i]) / det);
  }
  return s;
}

namespace {
double det_jacobian(const CutMesh& cut, const SubElement& e, double xi, double eta) {
  const Vec2& x0 = cut.x[e.node[0]];
  const Vec2& x1 = cut.x[e.node[1]];
  const Vec2& x2 = cut.x[e.node[2]];
  if (e.vertices == 3) {
    const Vec2 a = x1 - x0, b = x2 - x0;
    return a.x() * b.y() - a.y() * b.x();
  }
  const Vec2& x3 = cut.x[e.node[3]];
  const Vec2 t_xi = (1 - eta) * (x1 - x0) + eta * (x2 - x3);
  const Vec2 t_eta = (1 - xi) * (x3 - x0) + xi * (x2 - x1);
  return t_xi.x() * t_eta.y() - t_xi.y() * t_eta.x();
}

Vec2 map_point(const CutMesh& cut, const SubElement& e, const ShapeValues& s) {
  double x = 0.0, y = 0.0;  // component-wise: avoids a GCC 12 false -Wmaybe-uninitialized in Eigen
  for (int i = 0; i < s.n; ++i) {
    x += s.value[i] * cut.x[e.node[i]].x();
    y += s.value[i] * cut.x[e.node[i]].y();
  }
  return Vec2(x, y);
}
}  // namespace

void append_quadrature(const CutMesh& cut, const SubElement& e, std::vector<QuadraturePoint>& out) {
  if (e.vertices == 3) {
    static constexpr double kA = 1.0 / 6.0, kB = 2.0 / 3.0;
    static constexpr std::array<std::array<double, 2>, 3> pts{{{kA, kA}, {kB, kA}, {kA, kB}}};
    for (const auto& pt : pts) {
      const ShapeValues s = shape_at_reference(cut, e, pt[0], pt[1]);
      out.push_back(QuadraturePoint{s, map_point(cut, e, s),
                                    std::abs(det_jacobian(cut, e, pt[0], pt[1])) / 6.0});
    }
    return;
  }
  const double g = 0.5 / std::sqrt(3.0);
  for (double eta : {0.5 - g, 0.5 + g})
    for (double xi : {0.5 - g, 0.5 + g}) {
      const ShapeValues s = shape_at_reference(cut, e, xi, eta);
      out.push_back(QuadraturePoint{s, map_point(cut, e, s),
                                    std::abs(det_jacobian(cut, e, xi, eta)) * 0.25});
    }
}

std::array<double, 2> edge_reference(const SubElement& e, int i, double s) {
  if (e.vertices == 4) {
    switch (i) {
      case 0: return {s, 0.0};
      case 1: return {1.0, s};
      case 2: return {1.0 - s, 1.0};
      default: return {0.0, 1.0 - s};
    }
  }
  switch (i) {
    case 0: return {s, 0.0};
    case 1: return {1.0 - s, s};
    default: return {0.0, 1.0 - s};
  }
}

bool reference_coordinates(const CutMesh& cut, const SubElement& e, const Vec2& x, double& xi,
                           double& eta) {
  const Vec2& x0 = cut.x[e.node[0]];
  const Vec2& x1 = cut.x[e.node[1]];
  const Vec2& x2 = cut.x[e.node[2]];
  if (e.vertices == 3) {
    const Vec2 a = x1 - x0, b = x2 - x0, d = x - x0;
    const double det = a.x() * b.y() - a.y() * b.x();
    xi = (d.x() * b.y() - d.y() * b.x()) / det;
    eta = (a.x() * d.y() - a.y() * d.x()) / det;
    return std::isfinite(xi) && std::isfinite(eta);
  }
  const Vec2& x3 = cut.x[e.node[3]];
  xi = eta = 0.5;
  const double scale = (x2 - x0).norm() + (x3 - x1).norm();
  for (int it = 0; it < 30; ++it) {
    const Vec2 f = (1 - xi) * (1 - eta) * x0 + xi * (1 - eta) * x1 + xi * eta * x2 +
                   (1 - xi) * eta * x3 - x;
    if (f.norm() < 1e-14 * scale) return true;
    const Vec2 t_xi = (1 - eta) * (x1 - x0) + eta * (x2 - x3);
    const Vec2 t_eta = (1 - xi) * (x3 - x0) + xi * (x2 - x1);
    const double det = t_xi.x() * t_eta.y() - t_xi.y() * t_eta.x();
    xi -= (t_eta.y() * f.x() - t_eta.x() * f.y()) / det;
    eta -= (-t_xi.y() * f.x() + t_xi.x() * f.y()) / det;
    if (!std::isfinite(xi) || !std::isfinite(eta)) return false;
  }
  return true;  // converged to roundoff level or close enough for a margin test
}

double inside_margin(const SubElement& e, double xi, double eta) {
  if (e.vertices == 3) return std::min({xi, eta, 1.0 - xi - eta});
  return std::min({xi, eta, 1.0 - xi, 1.0 - eta});
}

QuadratureTable build_quadrature(const CutMesh& cut) {
  QuadratureTable table;
  table.points.reserve(4 * cut.elements.size());
  table.first.reserve(cut.elements.size() + 1);
  for (const SubElement& e : cut.elements) {
    table.first.push_back(static_cast<int>(table.points.size()));
    append_quadrature(cut, e, table.points);
  }
  table.first.push_back(static_cast<int>(table.points.size()));
  return table;
}

}  // namespace fsi::fe
