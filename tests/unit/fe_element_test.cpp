// Shape functions and quadrature of the sub-elements: partition of unity, reproduction
// of linear functions, exact integration of polynomials over cut meshes (degree 2 on
// triangles; degree 3 per direction on sub-quads, also bilinearly mapped ones), and the
// patch test: a discrete Laplace problem with linear Dirichlet data is solved exactly.
#include "fe/element.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fe_test_meshes.hpp"
#include "solve/sparse_lu.hpp"
#include "solve/sparsity.hpp"

namespace {

using fsi::test::Vec2;

/// Monomial integrals over a polygon (Green's theorem): {1, x, y, x^2, xy, y^2}.
std::array<double, 6> polygon_moments(const std::vector<Vec2>& v) {
  std::array<double, 6> m{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x0 = v[i].x(), y0 = v[i].y();
    const double x1 = v[(i + 1) % v.size()].x(), y1 = v[(i + 1) % v.size()].y();
    const double c = x0 * y1 - x1 * y0;
    m[0] += c / 2;
    m[1] += c * (x0 + x1) / 6;
    m[2] += c * (y0 + y1) / 6;
    m[3] += c * (x0 * x0 + x0 * x1 + x1 * x1) / 12;
    m[4] += c * (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) / 24;
    m[5] += c * (y0 * y0 + y0 * y1 + y1 * y1) / 12;
  }
  return m;
}

struct Case {
  std::string name;
  fsi::mesh::PatchMesh mesh;
  std::vector<Vec2> outline;
};

std::vector<Case> cases() {
  using fsi::Point2;
  const std::array<Point2, 4> quad{Point2{0.0, 0.0}, Point2{1.3, 0.2}, Point2{1.1, 1.0}, Point2{-0.2, 0.9}};
  return {{"graded", fsi::test::graded_square(6), {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}},
          {"mapped", fsi::test::block_mesh(9, 7, 1.0, 1.0, true, quad), {{0, 0}, {1.3, 0.2}, {1.1, 1.0}, {-0.2, 0.9}}}};
}

fsi::fe::CutMesh cut_by_circle(const fsi::mesh::PatchMesh& mesh, const std::vector<Vec2>& outline) {
  Vec2 c = Vec2::Zero();
  for (const Vec2& v : outline) c += 0.25 * v;
  return fsi::fe::build_cut_mesh(mesh, [c](const Vec2& x) { return (x - c - Vec2(0.03, -0.02)).norm() - 0.37; });
}

TEST(FeElement, ShapeFunctionsArePartitionOfUnityAndReproduceLinears) {
  for (const Case& k : cases()) {
    const auto cut = cut_by_circle(k.mesh, k.outline);
    const auto table = fsi::fe::build_quadrature(cut);
    for (int e = 0; e < cut.num_elements(); ++e)
      for (int q = table.first[e]; q < table.first[e + 1]; ++q) {
        const auto& p = table.points[q];
        const auto& el = cut.elements[e];
        double sum = 0.0;
        Vec2 x = Vec2::Zero(), grad_sum = Vec2::Zero();
        Eigen::Matrix2d grad_x = Eigen::Matrix2d::Zero();  // sum_i x_i grad N_i^T = I
        for (int i = 0; i < p.n; ++i) {
          sum += p.value[i];
          x += p.value[i] * cut.x[el.node[i]];
          grad_sum += p.grad[i];
          grad_x += cut.x[el.node[i]] * p.grad[i].transpose();
        }
        ASSERT_NEAR(sum, 1.0, 1e-14);
        ASSERT_NEAR((x - p.x).norm(), 0.0, 1e-14);
        ASSERT_NEAR(grad_sum.norm(), 0.0, 1e-9);
        ASSERT_NEAR((grad_x - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-11);
        ASSERT_GT(p.weight, 0.0);
      }
  }
}

TEST(FeElement, QuadratureIntegratesQuadraticsExactlyOverCutMeshes) {
  for (const Case& k : cases()) {
    SCOPED_TRACE(k.name);
    const auto cut = cut_by_circle(k.mesh, k.outline);
    const auto table = fsi::fe::build_quadrature(cut);
    std::array<double, 6> m{};
    for (const auto& p : table.points) {
      const double x = p.x.x(), y = p.x.y();
      const std::array<double, 6> f{1, x, y, x * x, x * y, y * y};
      for (int i = 0; i < 6; ++i) m[i] += p.weight * f[i];
    }
    const auto exact = polygon_moments(k.outline);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(m[i], exact[i], 1e-13) << "monomial " << i;
  }
}

TEST(FeElement, PatchTestLaplaceReproducesALinearSolution) {
  for (const Case& k : cases()) {
    SCOPED_TRACE(k.name);
    const auto cut = cut_by_circle(k.mesh, k.outline);
    const int n = k.mesh.num_nodes();
    auto a = fsi::solve::build_pattern(k.mesh, 1, {{1}}, {{0}});
    const auto table = fsi::fe::build_quadrature(cut);
    for (int e = 0; e < cut.num_elements(); ++e) {
      const auto& el = cut.elements[e];
      for (int q = table.first[e]; q < table.first[e + 1]; ++q) {
        const auto& p = table.points[q];
        for (int i = 0; i < p.n; ++i)
          for (int j = 0; j < p.n; ++j)
            a.valuePtr()[fsi::solve::value_index(a, el.node[i], el.node[j])] +=
                p.weight * p.grad[i].dot(p.grad[j]);
      }
    }
    auto exact = [](const Vec2& x) { return 1.0 + 2.0 * x.x() - 3.0 * x.y(); };
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for (int c = 0; c < n; ++c)
      for (int kk = a.outerIndexPtr()[c]; kk < a.outerIndexPtr()[c + 1]; ++kk) {
        const int r = a.innerIndexPtr()[kk];
        if (k.mesh.on_boundary[r]) {
          a.valuePtr()[kk] = r == c ? 1.0 : 0.0;
        } else if (k.mesh.on_boundary[c]) {
          rhs[r] -= a.valuePtr()[kk] * exact(cut.x[c]);
          a.valuePtr()[kk] = 0.0;
        }
      }
    for (int i = 0; i < n; ++i)
      if (k.mesh.on_boundary[i]) rhs[i] = exact(cut.x[i]);
    fsi::solve::SparseLU lu;
    ASSERT_TRUE(lu.factorize(a));
    const Eigen::VectorXd u = lu.solve(rhs);
    double err = 0.0;
    for (int i = 0; i < n; ++i) err = std::max(err, std::abs(u[i] - exact(cut.x[i])));
    EXPECT_LT(err, 1e-11);
  }
}

}  // namespace
