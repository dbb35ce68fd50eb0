// The hand-derived Jacobian of a fluid sub-element against the automatic
// differentiation of the same residual (which fsi_jacobian_test.cpp checks against
// finite differences): equal to round-off on quads and triangles, for extension and
// solid displacement rows, with and without the cavitation floor.
#include "forms/fluid_element_jacobian.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fe/cut_mesh.hpp"

namespace {

using fsi::forms::Jet;
using fsi::forms::kMaxLocal;

void expect_equal_to_automatic_differentiation(int vertices, std::array<char, 4> u_row_solid,
                                               const fsi::forms::FsiCoefficients& c, unsigned seed) {
  fsi::fe::CutMesh cut;
  cut.x = {{0.0, 0.0}, {0.1, 0.01}, {0.12, 0.09}, {-0.01, 0.1}};
  fsi::fe::SubElement e;
  e.vertices = vertices;
  e.node = {0, 1, 2, vertices == 4 ? 3 : -1};
  e.phase = fsi::Phase::fluid;
  e.patch = 0;
  std::vector<fsi::fe::QuadraturePoint> qp;
  fsi::fe::append_quadrature(cut, e, qp);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  std::vector<fsi::forms::OldValues> old;
  for (std::size_t q = 0; q < qp.size(); ++q) old.push_back({d(rng), d(rng), 0.1 * d(rng), 0.1 * d(rng), d(rng), d(rng)});
  fsi::forms::ElementInput in;
  in.element = &e;
  in.qp = qp.data();
  in.old = old.data();
  in.num_qp = static_cast<int>(qp.size());
  in.h_patch_m = 0.1;
  in.u_row_solid = u_row_solid;
  in.p_row_fluid = {1, 1, 1, 1};
  ASSERT_TRUE(fsi::forms::has_hand_jacobian(in));

  const int nl = 5 * vertices;
  std::array<double, kMaxLocal> x{};
  for (int i = 0; i < nl; ++i) x[i] = d(rng) * (i % 5 == 4 ? 20.0 : 1.0);
  std::array<Jet, kMaxLocal> xj, rj;
  for (int i = 0; i < kMaxLocal; ++i) xj[i] = i < nl ? Jet::variable(x[i], i) : Jet(0.0);
  fsi::forms::element_residual<Jet>(in, c, xj, rj);
  fsi::forms::ElementMatrix k;
  fsi::forms::fluid_element_jacobian(in, c, x, k);
  double scale = 0.0;
  for (int i = 0; i < nl; ++i)
    for (int j = 0; j < nl; ++j) scale = std::max(scale, std::abs(rj[i].d[j]));
  ASSERT_GT(scale, 0.0);
  for (int i = 0; i < nl; ++i)
    for (int j = 0; j < nl; ++j)
      EXPECT_NEAR(k[i][j], rj[i].d[j], 1e-13 * scale) << "row " << i << " col " << j;
}

fsi::forms::FsiCoefficients coefficients() {
  fsi::forms::FsiCoefficients c;
  c.k_s = 2e-3;
  c.rho_f = 1e3;
  c.nu_f = 1e-2;
  return c;
}

TEST(FluidElementJacobian, QuadWithExtensionAndSolidDisplacementRows) {
  expect_equal_to_automatic_differentiation(4, {1, 0, 1, 0}, coefficients(), 3);
}

TEST(FluidElementJacobian, TriangleWithExtensionRowsOnly) {
  expect_equal_to_automatic_differentiation(3, {0, 0, 0, 0}, coefficients(), 5);
}

// Nodal pressures in [-6, 6] Pa with p_cav = -1 Pa and a 2 Pa rounding: the quadrature
// points fall on the ramp's three branches.
TEST(FluidElementJacobian, QuadAcrossTheCavitationFloor) {
  for (unsigned seed : {7u, 11u, 13u}) {
    fsi::forms::FsiCoefficients c = coefficients();
    c.cavitation_p_pa = -1.0;
    c.cavitation_smoothing_pa = 2.0;
    expect_equal_to_automatic_differentiation(4, {0, 1, 0, 0}, c, seed);
  }
}

TEST(FluidElementJacobian, NotForSolidElementsNorOpenSides) {
  fsi::fe::SubElement e;
  e.phase = fsi::Phase::solid;
  fsi::forms::ElementInput in;
  in.element = &e;
  EXPECT_FALSE(fsi::forms::has_hand_jacobian(in));
  e.phase = fsi::Phase::fluid;
  EXPECT_TRUE(fsi::forms::has_hand_jacobian(in));
  in.num_open_sides = 1;
  EXPECT_FALSE(fsi::forms::has_hand_jacobian(in));
}

}  // namespace
