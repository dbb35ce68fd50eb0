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

// What locate finds, by searching every candidate patch in the buckets' order: the first
// sub-element that contains x, else the one with the best margin.
int first_containing_or_best(const fsi::fe::CutMesh& cut, const fsi::fe::PatchBuckets& buckets, const Vec2& x,
                             double tolerance) {
  int best = -1;
  double best_margin = -1e300;
  for (const auto* patches : {&buckets.candidates(x), &buckets.nearest_candidates(x)}) {
    for (int p : *patches)
      for (int k = cut.first_element[p]; k < cut.first_element[p + 1]; ++k) {
        double xi, eta;
        if (!fsi::fe::reference_coordinates(cut, cut.elements[k], x, xi, eta)) continue;
        const double m = fsi::fe::inside_margin(cut.elements[k], xi, eta);
        if (m > best_margin) {
          best_margin = m;
          best = k;
          if (m >= 0.0) return best;
        }
      }
  }
  return best_margin < -tolerance ? -1 : best;
}

// locate skips the patches whose box does not hold x: it must find the same sub-element
// as the search of every candidate, for points inside, on edges and nodes, in the thin
// rows of a graded mesh, and just outside the domain.
TEST(FePointLocator, FindsTheSubElementASearchOfEveryCandidateFindsFirst) {
  const auto mesh = fsi::test::graded_square(12);
  const Vec2 c(0.13, -0.71);
  const auto cut = fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return (x - c).norm() - 0.3; });
  const fsi::fe::PatchBuckets buckets(mesh);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0 - 1e-7, 1.0 + 1e-7);
  std::vector<Vec2> points;
  for (int k = 0; k < 4000; ++k) points.emplace_back(u(rng), u(rng));
  for (int k = 0; k < mesh.num_nodes(); ++k) points.push_back(cut.x[k]);
  for (const auto& s : cut.interface) points.push_back(0.5 * (s.a + s.b));
  int found = 0;
  for (const Vec2& x : points)
    for (double tolerance : {1e-8, 1e-6}) {
      const auto loc = fsi::fe::locate(cut, buckets, x, tolerance);
      ASSERT_EQ(loc.element, first_containing_or_best(cut, buckets, x, tolerance)) << x.transpose();
      found += loc.element >= 0;
    }
  EXPECT_GT(found, static_cast<int>(points.size()));
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
