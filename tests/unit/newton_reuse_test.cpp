// When Newton may start from a factorization it holds from an earlier solve
// (NewtonOptions::reuse_across_steps): chord steps with it, or a factorization first.
#include <gtest/gtest.h>

#include <vector>

#include "core/fsi_system.hpp"
#include "fe/cut_mesh.hpp"
#include "interface/body.hpp"
#include "mesh/patch_mesh.hpp"
#include "solve/newton.hpp"
#include "test_scenarios.hpp"

namespace {

/// The coarse Example 1's first step.
struct FirstStep {
  fsi::Scenario scenario = fsi::testing::coarse_example1();
  fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(scenario.mesh, scenario.walls);
  fsi::fe::CutMesh cut = fsi::fe::build_cut_mesh(
      mesh, [this](const Eigen::Vector2d& x) { return fsi::interface::initial_distance(scenario.body, x); });
  fsi::fe::QuadratureTable quadrature = fsi::fe::build_quadrature(cut);
  fsi::core::FsiSystem system{scenario, mesh};

  FirstStep() {
    system.set_geometry(cut, quadrature, scenario.numerics.time_step_s);
    system.set_old_values(std::vector<fsi::forms::OldValues>(quadrature.points.size()));
  }
};

TEST(NewtonReuse, AHeldFactorizationServesTheNextSolveOnlyIfAllowed) {
  FirstStep s;
  for (const bool reuse : {true, false}) {
    fsi::solve::NewtonSolver newton(s.system.pattern());
    fsi::solve::NewtonOptions options;
    options.reuse_across_steps = reuse;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(s.system.size());
    const fsi::solve::NewtonResult first = newton.solve(s.system, x, options);
    ASSERT_TRUE(first.converged);
    ASSERT_GE(first.factorizations, 1);
    // The same system from a start a little off the solution: the held factorization is
    // the Jacobian at (almost) this point, and chord steps with it contract at once.
    x *= 1.01;
    const fsi::solve::NewtonResult second = newton.solve(s.system, x, options);
    EXPECT_TRUE(second.converged) << "reuse " << reuse;
    EXPECT_EQ(second.factorizations, reuse ? 0 : 1) << "reuse " << reuse;
  }
}

}  // namespace
