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
  // + S_aniso(p, xi) in the divergence rows (gamma / (rho nu) with rho nu = 1).
  const std::vector<fe::StabilizationEdge> edges = fe::build_stabilization_edges(cut);
  forms::add_pressure_stabilization(mesh, cut, edges, gamma, kStride, 2, a);

  std::vector<char> fixed(kStride * n, 0);
  Eigen::VectorXd value = Eigen::VectorXd::Zero(kStride * n);
  int pinned = -1;
  for (int i = 0; i < n; ++i) {
    if (mesh.on_boundary[i] || cut.touches_solid[i])
      for (int d = 0; d < 2; ++d) {
        fixed[kStride * i + d] = 1;
        value[kStride * i + d] = velocity(cut.x[i])[d];
      }
    if (!cut.touches_fluid[i]) fixed[kStride * i + 2] = 1;  // p = 0, excluded
    if (pinned < 0 && mesh.on_boundary[i] && cut.touches_fluid[i]) pinned = i;
  }
  fixed[kStride * pinned + 2] = 1;
  value[kStride * pinned + 2] = pressure(cut.x[pinned]);
  apply_dirichlet(a, rhs, fixed, value);

  solve::SparseLU lu;
  result.factorized = lu.factorize(a);
  result.rcond = lu.rcond();
  if (!result.factorized) return result;
  const Eigen::VectorXd x = lu.solve(rhs);

  // Mean of the pressure error over the discrete fluid domain, then the norms.
  double area = 0.0, mean = 0.0, v_l2 = 0.0;
  std::vector<std::vector<fe::QuadraturePoint>> rules(cut.elements.size());
  for (std::size_t k = 0; k < cut.elements.size(); ++k) {
    const fe::SubElement& e = cut.elements[k];
    if (e.phase != Phase::fluid) continue;
    rules[k] = error_quadrature(cut, e);
    for (const fe::QuadraturePoint& q : rules[k]) {
      double ph = 0.0;
      Vec2 vh = Vec2::Zero();
      for (int i = 0; i < q.n; ++i) {
        ph += q.value[i] * x[kStride * e.node[i] + 2];
        vh += q.value[i] * Vec2(x[kStride * e.node[i]], x[kStride * e.node[i] + 1]);
      }
      area += q.weight;
      mean += q.weight * (ph - pressure(q.x));
      v_l2 += q.weight * (vh - velocity(q.x)).squaredNorm();
    }
  }
  mean /= area;
  double p_l2 = 0.0;
  for (std::size_t k = 0; k < cut.elements.size(); ++k) {
    const fe::SubElement& e = cut.elements[k];
    for (const fe::QuadraturePoint& q : rules[k]) {
      double ph = 0.0;
      for (int i = 0; i < q.n; ++i) ph += q.value[i] * x[kStride * e.node[i] + 2];
      p_l2 += q.weight * std::pow(ph - mean - pressure(q.x), 2);
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
    const double ph = x[kStride * i + 2] - mean;
    result.pressure_max = std::max(result.pressure_max, std::abs(ph - pressure(cut.x[i])));
    if (mesh.nodes[i].y() == row_y) result.line.push_back({cut.x[i].x(), ph, pressure(cut.x[i])});
  }
  std::sort(result.line.begin(), result.line.end());
  return result;
}

}  // namespace fsi::study
