#include "stokes_cip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "error_quadrature.hpp"
#include "fe/element.hpp"
#include "fe/stabilization_edges.hpp"
#include "forms/pressure_stabilization.hpp"
#include "linear_system.hpp"
#include "solve/sparse_lu.hpp"

namespace fsi::study {
namespace {

using mesh::Vec2;
constexpr double kPi = std::numbers::pi;
constexpr int kStride = 3;  // vx, vy, p per node

Vec2 velocity(const Vec2& x) {
  return {std::sin(kPi * x.x()) * std::cos(kPi * x.y()), -std::cos(kPi * x.x()) * std::sin(kPi * x.y())};
}
double pressure(const Vec2& x) { return std::sin(kPi * x.x()) * std::cos(0.5 * kPi * x.y()) + x.x() * x.y(); }
Vec2 grad_pressure(const Vec2& x) {
  return {kPi * std::cos(kPi * x.x()) * std::cos(0.5 * kPi * x.y()) + x.y(),
          -0.5 * kPi * std::sin(kPi * x.x()) * std::sin(0.5 * kPi * x.y()) + x.x()};
}
/// -Laplace(v) = 2 pi^2 v for this v.
Vec2 force(const Vec2& x) { return 2.0 * kPi * kPi * velocity(x) + grad_pressure(x); }
/// Do-nothing data on the outflow x = 1 (normal (1, 0)): g = dv/dn - p n.
Vec2 outflow_traction(const Vec2& x) {
  return {kPi * std::cos(kPi * x.x()) * std::cos(kPi * x.y()) - pressure(x),
          kPi * std::sin(kPi * x.x()) * std::sin(kPi * x.y())};
}
bool on_outflow(const Vec2& x) { return std::abs(x.x() - 1.0) < 1e-12; }

}  // namespace

StokesResult solve_stokes_cip(const mesh::PatchMesh& mesh, const Circle& circle, double gamma) {
  const fe::CutMesh cut = fe::build_cut_mesh(
      mesh, [&](const Vec2& x) { return (x - circle.centre).norm() - circle.radius; });
  const int n = mesh.num_nodes();
  StokesResult result;
  result.nodes = n;

  const solve::FieldCoupling all(3, std::vector<char>(3, 1));
  const solve::FieldCoupling pp{{0, 0, 0}, {0, 0, 0}, {0, 0, 1}};
  solve::SparseMatrix a = solve::build_pattern(mesh, kStride, all, pp);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(kStride * n);
  std::vector<fe::QuadraturePoint> points;
  for (const fe::SubElement& e : cut.elements) {
    if (e.phase != Phase::fluid) continue;
    points.clear();
    fe::append_quadrature(cut, e, points);
    for (const fe::QuadraturePoint& q : points) {
      const Vec2 f = force(q.x);
      for (int i = 0; i < q.n; ++i) {
        const int row = kStride * e.node[i];
        for (int d = 0; d < 2; ++d) rhs[row + d] += q.weight * f[d] * q.value[i];
        for (int j = 0; j < q.n; ++j) {
          const int col = kStride * e.node[j];
          const double lap = q.weight * q.grad[i].dot(q.grad[j]);
          for (int d = 0; d < 2; ++d) {
            add_entry(a, row + d, col + d, lap);                                     // (grad v, grad phi)
            add_entry(a, row + d, col + 2, -q.weight * q.value[j] * q.grad[i][d]);  // -(p, div phi)
            add_entry(a, row + 2, col + d, q.weight * q.value[i] * q.grad[j][d]);   // (div v, xi)
          }
        }
      }
    }
  }
  // Outflow x = 1: the natural condition of the momentum equation, dv/dn - p n = g, adds
  // (g, phi) on the boundary (3-point Gauss along each sub-element side; the trace of
  // both Q1 and P1 is linear along a straight side). It also fixes the pressure level.
  for (const fe::SubElement& e : cut.elements) {
    if (e.phase != Phase::fluid) continue;
    for (int i = 0; i < e.vertices; ++i) {
      const int na = e.node[i], nb = e.node[(i + 1) % e.vertices];
      if (!on_outflow(mesh.nodes[na]) || !on_outflow(mesh.nodes[nb])) continue;
      const double length = (cut.x[nb] - cut.x[na]).norm();
      const double g = 0.5 * std::sqrt(0.6);
      for (const auto& [t, w] : {std::array<double, 2>{0.5 - g, 5.0 / 18.0}, {0.5, 8.0 / 18.0},
                                 {0.5 + g, 5.0 / 18.0}}) {
        const Vec2 traction = outflow_traction((1 - t) * cut.x[na] + t * cut.x[nb]);
        for (int d = 0; d < 2; ++d) {
          rhs[kStride * na + d] += w * length * (1 - t) * traction[d];
          rhs[kStride * nb + d] += w * length * t * traction[d];
        }
      }
    }
  }

  // + S_aniso(p, xi) in the divergence rows (gamma / (rho nu) with rho nu = 1).
  const std::vector<fe::StabilizationEdge> edges = fe::build_stabilization_edges(cut);
  forms::add_pressure_stabilization(mesh, cut, edges, gamma, kStride, 2, a);

  std::vector<char> fixed(kStride * n, 0);
  Eigen::VectorXd value = Eigen::VectorXd::Zero(kStride * n);
  for (int i = 0; i < n; ++i) {
    const bool dirichlet = (mesh.on_boundary[i] && !on_outflow(mesh.nodes[i])) ||
                           std::abs(std::abs(mesh.nodes[i].y()) - 1.0) < 1e-12;
    if (dirichlet || cut.touches_solid[i])
      for (int d = 0; d < 2; ++d) {
        fixed[kStride * i + d] = 1;
        value[kStride * i + d] = velocity(cut.x[i])[d];
      }
    if (!cut.touches_fluid[i]) fixed[kStride * i + 2] = 1;  // p = 0, excluded
  }
  apply_dirichlet(a, rhs, fixed, value);

  solve::SparseLU lu;
  result.factorized = lu.factorize(a);
  result.rcond = lu.rcond();
  if (!result.factorized) return result;
  const Eigen::VectorXd x = lu.solve(rhs);

  // Errors over the discrete fluid domain (the outflow fixes the pressure level: no
  // mean correction).
  double v_l2 = 0.0, p_l2 = 0.0;
  for (const fe::SubElement& e : cut.elements) {
    if (e.phase != Phase::fluid) continue;
    for (const fe::QuadraturePoint& q : error_quadrature(cut, e)) {
      double ph = 0.0;
      Vec2 vh = Vec2::Zero();
      for (int i = 0; i < q.n; ++i) {
        ph += q.value[i] * x[kStride * e.node[i] + 2];
        vh += q.value[i] * Vec2(x[kStride * e.node[i]], x[kStride * e.node[i] + 1]);
      }
      p_l2 += q.weight * std::pow(ph - pressure(q.x), 2);
      v_l2 += q.weight * (vh - velocity(q.x)).squaredNorm();
    }
  }
  result.velocity_l2 = std::sqrt(v_l2);
  result.pressure_l2 = std::sqrt(p_l2);

  // Nodal max-norm of the pressure error, and the profile along a grid row.
  double row_y = cut.x[0].y();
  for (int i = 0; i < n; ++i)
    if (std::abs(mesh.nodes[i].y() - 0.75) < std::abs(row_y - 0.75)) row_y = mesh.nodes[i].y();
  for (int i = 0; i < n; ++i) {
    if (!cut.touches_fluid[i]) continue;
    const double ph = x[kStride * i + 2];
    result.pressure_max = std::max(result.pressure_max, std::abs(ph - pressure(cut.x[i])));
    if (mesh.nodes[i].y() == row_y) result.line.push_back({cut.x[i].x(), ph, pressure(cut.x[i])});
  }
  std::sort(result.line.begin(), result.line.end());
  return result;
}

}  // namespace fsi::study
