// Point location in a cut mesh and evaluation of FE functions: the located element's
// map reproduces the point, linear functions are evaluated exactly (value and gradient)
// also on nodes, on sub-element edges and inside cut patches; points outside the domain
// beyond the tolerance are not found.
#include "fe/point_locator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fe_test_meshes.hpp"

namespace {

using fsi::test::Vec2;

TEST(FePointLocator, FindsPointsAndEvaluatesLinearFunctionsExactly) {
  const auto mesh = fsi::test::graded_square(10);
  const Vec2 c(0.07, -0.11);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return (x - c).norm() - 0.5; });
  const fsi::fe::PatchBuckets buckets(mesh);
  auto f = [](const Vec2& x) { return 0.5 - 1.5 * x.x() + 2.5 * x.y(); };
  Eigen::VectorXd coeffs(2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    coeffs[2 * i] = -7.0;  // another field interleaved: stride/offset must be honoured
    coeffs[2 * i + 1] = f(cut.x[i]);
  }
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> points;
  for (int k = 0; k < 2000; ++k) points.emplace_back(u(rng), u(rng));
  for (int k = 0; k < mesh.num_nodes(); k += 7) points.push_back(cut.x[k]);  // nodes (moved ones too)
  for (const auto& s : cut.interface) points.push_back(0.5 * (s.a + s.b));     // on interface edges
  points.emplace_back(1.0, 1.0);
  points.emplace_back(-1.0, 0.3);
  for (const Vec2& x : points) {
    const auto loc = fsi::fe::locate(cut, buckets, x);
    ASSERT_GE(loc.element, 0) << x.transpose();
    EXPECT_GE(loc.margin, -1e-10);
    const auto& e = cut.elements[loc.element];
    Vec2 mapped = Vec2::Zero();
    for (int i = 0; i < e.vertices; ++i) mapped += loc.shape.value[i] * cut.x[e.node[i]];
    EXPECT_NEAR((mapped - x).norm(), 0.0, 1e-12);
    EXPECT_NEAR(fsi::fe::evaluate(cut, loc, coeffs, 2, 1), f(x), 1e-12);
    EXPECT_NEAR((fsi::fe::evaluate_gradient(cut, loc, coeffs, 2, 1) - Vec2(-1.5, 2.5)).norm(), 0.0, 1e-9);
  }
}

TEST(FePointLocator, RejectsPointsOutsideTheDomain) {
  const auto mesh = fsi::test::block_mesh(4, 4, 1.0, 1.0);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [](const Vec2& x) { return x.x() - 0.37; });
  const fsi::fe::PatchBuckets buckets(mesh);
  EXPECT_EQ(fsi::fe::locate(cut, buckets, Vec2(1.1, 0.5)).element, -1);
  EXPECT_EQ(fsi::fe::locate(cut, buckets, Vec2(-0.01, 0.5)).element, -1);
  EXPECT_GE(fsi::fe::locate(cut, buckets, Vec2(1.0 + 1e-12, 0.5)).element, 0);  // within tolerance
}

}  // namespace
