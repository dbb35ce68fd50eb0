#include "error_quadrature.hpp"

#include <array>
#include <cmath>

namespace fsi::study {
namespace {

/// |det J| of the element map at reference point (xi, eta).
double jacobian(const fe::CutMesh& cut, const fe::SubElement& e, double xi, double eta) {
  const mesh::Vec2& x0 = cut.x[e.node[0]];
  const mesh::Vec2& x1 = cut.x[e.node[1]];
  const mesh::Vec2& x2 = cut.x[e.node[2]];
  mesh::Vec2 t_xi = x1 - x0, t_eta = x2 - x0;
  if (e.vertices == 4) {
    const mesh::Vec2& x3 = cut.x[e.node[3]];
    t_xi = (1 - eta) * (x1 - x0) + eta * (x2 - x3);
    t_eta = (1 - xi) * (x3 - x0) + xi * (x2 - x1);
  }
  return std::abs(t_xi.x() * t_eta.y() - t_xi.y() * t_eta.x());
}

fe::QuadraturePoint point(const fe::CutMesh& cut, const fe::SubElement& e, double xi, double eta,
                          double ref_weight) {
  fe::QuadraturePoint q;
  static_cast<fe::ShapeValues&>(q) = fe::shape_at_reference(cut, e, xi, eta);
  double x = 0.0, y = 0.0;
  for (int i = 0; i < q.n; ++i) {
    x += q.value[i] * cut.x[e.node[i]].x();
    y += q.value[i] * cut.x[e.node[i]].y();
  }
  q.x = mesh::Vec2(x, y);
  q.weight = ref_weight * jacobian(cut, e, xi, eta);
  return q;
}

}  // namespace

std::vector<fe::QuadraturePoint> error_quadrature(const fe::CutMesh& cut, const fe::SubElement& e) {
  std::vector<fe::QuadraturePoint> out;
  if (e.vertices == 4) {
    // Gauss-Legendre, 3 points on [0,1].
    const double g = 0.5 * std::sqrt(0.6);
    const std::array<double, 3> x{0.5 - g, 0.5, 0.5 + g};
    const std::array<double, 3> w{5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) out.push_back(point(cut, e, x[i], x[j], w[i] * w[j]));
    return out;
  }
  // Degree-5 7-point rule on the reference triangle (weights sum to 1/2).
  const double s = std::sqrt(15.0);
  const double a1 = (6.0 - s) / 21.0, b1 = (9.0 + 2.0 * s) / 21.0;
  const double a2 = (6.0 + s) / 21.0, b2 = (9.0 - 2.0 * s) / 21.0;
  const double w1 = (155.0 - s) / 2400.0, w2 = (155.0 + s) / 2400.0;
  out.push_back(point(cut, e, 1.0 / 3.0, 1.0 / 3.0, 9.0 / 80.0));
  for (const auto& [xi, eta] : {std::array<double, 2>{a1, a1}, {b1, a1}, {a1, b1}})
    out.push_back(point(cut, e, xi, eta, w1));
  for (const auto& [xi, eta] : {std::array<double, 2>{a2, a2}, {b2, a2}, {a2, b2}})
    out.push_back(point(cut, e, xi, eta, w2));
  return out;
}

}  // namespace fsi::study
