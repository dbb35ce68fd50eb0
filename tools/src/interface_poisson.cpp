#include "interface_poisson.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "error_quadrature.hpp"
#include "fe/element.hpp"
#include "linear_system.hpp"
#include "solve/sparse_lu.hpp"

namespace fsi::study {
namespace {

using mesh::Vec2;

constexpr double kKappaIn = 1.0;    // solid phase (phi < 0)
constexpr double kKappaOut = 10.0;  // fluid phase

/// w = (|x-c|^2 - r0^2) s(x) and its derivatives (see the header).
struct Manufactured {
  Circle circle;

  double s(const Vec2& x) const { return 1.0 + 0.5 * std::sin(2 * x.x()) * std::cos(x.y()); }
  Vec2 grad_s(const Vec2& x) const {
    return {std::cos(2 * x.x()) * std::cos(x.y()), -0.5 * std::sin(2 * x.x()) * std::sin(x.y())};
  }
  double g(const Vec2& x) const {
    return (x - circle.centre).squaredNorm() - circle.radius * circle.radius;
  }
  double w(const Vec2& x) const { return g(x) * s(x); }
  Vec2 grad_w(const Vec2& x) const { return 2.0 * (x - circle.centre) * s(x) + g(x) * grad_s(x); }
  /// f = -Laplace(w) = -(4 s + 4 (x - c) . grad s + g Laplace(s)), Laplace(s) = -5/2 sin 2x cos y.
  double f(const Vec2& x) const {
    const double lap_s = -2.5 * std::sin(2 * x.x()) * std::cos(x.y());
    return -(4.0 * s(x) + 4.0 * (x - circle.centre).dot(grad_s(x)) + g(x) * lap_s);
  }
};

double kappa(Phase p) { return p == Phase::solid ? kKappaIn : kKappaOut; }

}  // namespace

PoissonResult solve_interface_poisson(const mesh::PatchMesh& mesh, const Circle& circle) {
  const Manufactured exact{circle};
  const fe::CutMesh cut = fe::build_cut_mesh(
      mesh, [&](const Vec2& x) { return (x - circle.centre).norm() - circle.radius; });
  const int n = mesh.num_nodes();

  PoissonResult result;
  result.nodes = n;
  result.saddle_patches = cut.saddle_patches;
  result.min_angle = std::numbers::pi;
  for (const fe::SubElement& e : cut.elements) {
    const auto [lo, hi] = fe::element_angle_range(cut, e);
    result.min_angle = std::min(result.min_angle, lo);
    result.max_angle = std::max(result.max_angle, hi);
  }
  for (fe::PatchKind k : cut.kind) result.cut_patches += k != fe::PatchKind::uncut;

  // (kappa grad u, grad phi_i) = (f, phi_i), assembled sub-element by sub-element with
  // the assembly rule (2x2 Gauss / 3-point degree 2), kappa from the element's phase.
  solve::SparseMatrix a = solve::build_pattern(mesh, 1, {{1}}, {{0}});
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  std::vector<fe::QuadraturePoint> points;
  for (const fe::SubElement& e : cut.elements) {
    points.clear();
    fe::append_quadrature(cut, e, points);
    const double k = kappa(e.phase);
    for (const fe::QuadraturePoint& q : points)
      for (int i = 0; i < q.n; ++i) {
        rhs[e.node[i]] += q.weight * exact.f(q.x) * q.value[i];
        for (int j = 0; j < q.n; ++j)
          add_entry(a, e.node[i], e.node[j], q.weight * k * q.grad[i].dot(q.grad[j]));
      }
  }
  // Dirichlet data on the outer boundary (outside the circle: u = w / kappa_out).
  std::vector<char> fixed(n, 0);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i)
    if (mesh.on_boundary[i]) {
      fixed[i] = 1;
      g[i] = exact.w(cut.x[i]) / kKappaOut;
    }
  apply_dirichlet(a, rhs, fixed, g);

  solve::SparseLU lu;
  result.factorized = lu.factorize(a);
  result.rcond = lu.rcond();
  if (!result.factorized) return result;
  const Eigen::VectorXd u = lu.solve(rhs);

  // Errors against the formula of the sub-element's own (discrete) phase.
  double l2 = 0.0, h1 = 0.0;
  for (const fe::SubElement& e : cut.elements) {
    const double k = kappa(e.phase);
    for (const fe::QuadraturePoint& q : error_quadrature(cut, e)) {
      double uh = 0.0;
      Vec2 grad_uh = Vec2::Zero();
      for (int i = 0; i < q.n; ++i) {
        uh += q.value[i] * u[e.node[i]];
        grad_uh += q.grad[i] * u[e.node[i]];
      }
      l2 += q.weight * std::pow(exact.w(q.x) / k - uh, 2);
      h1 += q.weight * (exact.grad_w(q.x) / k - grad_uh).squaredNorm();
    }
  }
  result.l2_error = std::sqrt(l2);
  result.h1_error = std::sqrt(h1);
  return result;
}

}  // namespace fsi::study
