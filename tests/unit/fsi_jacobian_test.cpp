// The exact Jacobian (automatic differentiation of the element residual) against
// central finite differences of the residual, for fluid and solid sub-elements and
// for the assembled system.
#include "forms/fsi_element.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/fsi_system.hpp"
#include "solve/sparsity.hpp"
#include "fe/cut_mesh.hpp"
#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"
#include "test_scenarios.hpp"

namespace {

using fsi::forms::Jet;
using fsi::forms::kMaxLocal;

struct ElementFixture {
  fsi::fe::CutMesh cut;
  std::vector<fsi::fe::QuadraturePoint> qp;
  std::vector<fsi::forms::OldValues> old;
  fsi::forms::OpenBoundarySide side;
  fsi::forms::ElementInput input;

  ElementFixture(int vertices, fsi::Phase phase) {
    cut.x = {{0.0, 0.0}, {0.1, 0.01}, {0.12, 0.09}, {-0.01, 0.1}};
    fsi::fe::SubElement& e = element;
    e.vertices = vertices;
    e.node = {0, 1, 2, vertices == 4 ? 3 : -1};
    e.phase = phase;
    e.patch = 0;
    fsi::fe::append_quadrature(cut, e, qp);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(-0.3, 0.3);
    for (std::size_t q = 0; q < qp.size(); ++q) old.push_back({d(rng), d(rng), 0.1 * d(rng), 0.1 * d(rng), d(rng), d(rng)});
    const auto ref = fsi::fe::edge_reference(e, 0, 0.3);
    side.shape[0] = side.shape[1] = fsi::fe::shape_at_reference(cut, e, ref[0], ref[1]);
    side.weight = {0.05, 0.05};
    side.nx = 0.1;
    side.ny = -1.0;
    input.element = &element;
    input.qp = qp.data();
    input.old = old.data();
    input.num_qp = static_cast<int>(qp.size());
    input.h_patch_m = 0.1;
    input.u_row_solid = {1, 0, 1, 0};
    input.p_row_fluid = {0, 1, 1, 0};
    input.open_sides = &side;
    input.num_open_sides = 1;
  }
  fsi::fe::SubElement element;
};

void check_element(int vertices, fsi::Phase phase) {
  ElementFixture f(vertices, phase);
  fsi::forms::FsiCoefficients c;
  c.mu_s = 2e3;  // soft enough that the nonlinearity shows at these displacements
  c.lambda_s = 8e3;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  const int nl = 5 * vertices;
  std::array<double, kMaxLocal> x{};
  for (int i = 0; i < nl; ++i) x[i] = d(rng) * (i % 5 == 4 ? 100.0 : 1.0);
  std::array<Jet, kMaxLocal> xj, rj;
  for (int i = 0; i < kMaxLocal; ++i) xj[i] = i < nl ? Jet::variable(x[i], i) : Jet(0.0);
  fsi::forms::element_residual<Jet>(f.input, c, xj, rj);
  for (int j = 0; j < nl; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[j]));
    std::array<double, kMaxLocal> xp = x, xm = x, rp, rm;
    xp[j] += h;
    xm[j] -= h;
    fsi::forms::element_residual<double>(f.input, c, xp, rp);
    fsi::forms::element_residual<double>(f.input, c, xm, rm);
    for (int i = 0; i < nl; ++i) {
      const double fd = (rp[i] - rm[i]) / (2 * h);
      EXPECT_NEAR(rj[i].d[j], fd, 1e-6 * (1.0 + std::abs(fd))) << "row " << i << " col " << j;
    }
  }
}

TEST(FsiJacobian, FluidTriangle) { check_element(3, fsi::Phase::fluid); }
TEST(FsiJacobian, FluidQuadWithOpenBoundary) { check_element(4, fsi::Phase::fluid); }
TEST(FsiJacobian, SolidTriangle) { check_element(3, fsi::Phase::solid); }
TEST(FsiJacobian, SolidQuad) { check_element(4, fsi::Phase::solid); }

TEST(FsiJacobian, AssembledSystemMatchesFiniteDifferences) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.solid.mu_pa = 2e3;
  s.solid.lambda_pa = 8e3;
  const auto mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [&](const fsi::mesh::Vec2& x) {
    return fsi::interface::initial_distance(s.body, x);
  });
  const auto quad = fsi::fe::build_quadrature(cut);
  fsi::core::FsiSystem system(s, mesh);
  system.set_geometry(cut, quad, 0.01);
  system.set_old_values(std::vector<fsi::forms::OldValues>(quad.points.size()));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  Eigen::VectorXd x(system.size());
  // Velocities ~ 2 cm/s, displacements ~ 1 mm (strains of a few percent), pressures ~ 10 Pa.
  for (int i = 0; i < x.size(); ++i) x[i] = d(rng) * (i % 5 == 4 ? 500.0 : (i % 5 >= 2 ? 0.05 : 1.0));
  Eigen::VectorXd r, rp, rm;
  auto jac = system.pattern();
  system.residual_and_jacobian(x, r, jac);
  Eigen::VectorXd r_plain;
  system.residual(x, r_plain);
  EXPECT_LT((r - r_plain).norm(), 1e-12 * (1.0 + r.norm()));
  const Eigen::MatrixXd dense = Eigen::MatrixXd(jac);
  for (int col = 0; col < x.size(); col += 97) {
    Eigen::VectorXd xp = x, xm = x;
    const double h = 1e-6;
    xp[col] += h;
    xm[col] -= h;
    system.residual(xp, rp);
    system.residual(xm, rm);
    const Eigen::VectorXd fd = (rp - rm) / (2 * h);
    EXPECT_LT((fd - dense.col(col)).norm(), 1e-5 * (1.0 + fd.norm())) << "column " << col;
  }
}

}  // namespace
