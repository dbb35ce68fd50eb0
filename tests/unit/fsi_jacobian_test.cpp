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

fsi::forms::FsiCoefficients test_coefficients() {
  fsi::forms::FsiCoefficients c;
  c.mu_s = 2e3;  // soft enough that the nonlinearity shows at these displacements
  c.lambda_s = 8e3;
  return c;
}

void check_element(int vertices, fsi::Phase phase,
                   const fsi::forms::FsiCoefficients& c = test_coefficients()) {
  ElementFixture f(vertices, phase);
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

// The nodal pressures lie in [-5, 5] Pa: with p_cav = -1 Pa and a rounding width of
// 1 Pa the quadrature points fall on all three branches of the ramp.
TEST(FsiJacobian, FluidQuadAcrossTheCavitationFloor) {
  fsi::forms::FsiCoefficients c = test_coefficients();
  c.cavitation_p_pa = -1.0;
  c.cavitation_smoothing_pa = 1.0;
  check_element(4, fsi::Phase::fluid, c);
}

// The random nodal velocities give the side's Gauss point an inflow: the backflow term
// (v.n)_- v is in the derivative check.
TEST(FsiJacobian, FluidQuadWithBackflowStabilization) {
  fsi::forms::FsiCoefficients c = test_coefficients();
  c.backflow_beta = 1.0;
  check_element(4, fsi::Phase::fluid, c);
}

// A uniform velocity through the open side (grad v = 0: the do-nothing correction is
// zero). Outflow: the backflow term adds nothing. Inflow: tested with v it adds
// beta rho_f / 2 |v.n| |v|^2 times the side's length (the weights of its two points),
// which is the kinetic energy flux the inflow brings in.
TEST(FsiBackflow, TheTermTakesOutTheKineticEnergyOfTheInflowOnly) {
  ElementFixture f(4, fsi::Phase::fluid);
  fsi::forms::FsiCoefficients plain = test_coefficients(), stabilized = plain;
  stabilized.backflow_beta = 1.0;
  auto extra_power = [&](double vx, double vy) {
    std::array<double, kMaxLocal> x{}, r0{}, r1{};
    for (int a = 0; a < 4; ++a) {
      x[5 * a] = vx;
      x[5 * a + 1] = vy;
    }
    fsi::forms::element_residual<double>(f.input, plain, x, r0);
    fsi::forms::element_residual<double>(f.input, stabilized, x, r1);
    double power = 0.0;
    for (int a = 0; a < 4; ++a) power += (r1[5 * a] - r0[5 * a]) * vx + (r1[5 * a + 1] - r0[5 * a + 1]) * vy;
    return power;
  };
  const double length = f.side.weight[0] + f.side.weight[1];
  // n = (0.1, -1): v = (0, -0.3) leaves, v = (0.2, 0.4) enters with v.n = -0.38.
  EXPECT_EQ(extra_power(0.0, -0.3), 0.0);
  const double vn = 0.2 * f.side.nx + 0.4 * f.side.ny, v2 = 0.2 * 0.2 + 0.4 * 0.4;
  const double expected = 0.5 * stabilized.rho_f * (-vn) * v2 * length;
  EXPECT_NEAR(extra_power(0.2, 0.4), expected, 1e-12 * expected);
}

// A fluid element at rest with a uniform nodal pressure p: the pressure rows hold
// -ramp(p_cav - p) / (rho_f nu_f) (xi, 1). Above the floor plus the rounding they are
// zero, far below it the fluid expands at (p_cav - p) / (rho_f nu_f).
TEST(FsiCavitation, TheFluidExpandsOnlyBelowTheFloor) {
  ElementFixture f(4, fsi::Phase::fluid);
  f.input.num_open_sides = 0;
  fsi::forms::FsiCoefficients c = test_coefficients();
  c.cavitation_p_pa = -1.0e4;
  c.cavitation_smoothing_pa = 2.5e3;
  const double mu = c.rho_f * c.nu_f;
  auto pressure_rows = [&](double p) {
    std::array<double, kMaxLocal> x{}, r{};
    for (int a = 0; a < 4; ++a) x[5 * a + 4] = p;
    fsi::forms::element_residual<double>(f.input, c, x, r);
    return std::array<double, 4>{r[4], r[9], r[14], r[19]};
  };
  double area = 0.0;
  for (const auto& q : f.qp) area += q.weight;
  double sum_above = 0.0, sum_below = 0.0;
  for (double r : pressure_rows(-8.0e3)) sum_above += r;  // floor + w/2 = -8.75e3 < p
  for (double r : pressure_rows(-3.0e4)) sum_below += r;
  EXPECT_EQ(sum_above, 0.0);
  // sum over the nodes of (xi_a, 1) is the element area (partition of unity).
  EXPECT_NEAR(sum_below, -(2.0e4 / mu) * area, 1e-9 * (2.0e4 / mu) * area);
}

TEST(FsiCavitation, RoundedRampIsContinuousWithItsDerivative) {
  const double w = 2.0;
  EXPECT_EQ(fsi::forms::rounded_ramp(-1.0, w), 0.0);
  EXPECT_DOUBLE_EQ(fsi::forms::rounded_ramp(0.0, w), 0.25);  // w/8: above max(0, x)
  EXPECT_DOUBLE_EQ(fsi::forms::rounded_ramp(1.0, w), 1.0);
  const Jet left = fsi::forms::rounded_ramp(Jet::variable(-1.0 + 1e-12, 0), w);
  const Jet right = fsi::forms::rounded_ramp(Jet::variable(1.0 - 1e-12, 0), w);
  EXPECT_NEAR(left.d[0], 0.0, 1e-9);
  EXPECT_NEAR(right.d[0], 1.0, 1e-9);
}

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
