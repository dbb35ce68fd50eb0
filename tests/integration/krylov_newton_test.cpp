// numerics.krylov_iterations: Newton's directions from GMRES on an older factorization
// instead of a new one. The same steps to Newton's tolerance, with fewer factorizations.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include "test_scenarios.hpp"

namespace {

struct BallRun {
  fsi::Functionals last;
  int factorizations = 0, jacobian_assemblies = 0, krylov_iterations = 0, steps_converged = 0;
};

BallRun falling_ball(int krylov_iterations, int steps) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.krylov_iterations = krylov_iterations;
  fsi::Engine engine(s);
  BallRun run;
  for (int i = 0; i < steps; ++i) {
    const fsi::StepReport r = engine.step();
    run.factorizations += r.factorizations;
    run.jacobian_assemblies += r.jacobian_assemblies;
    run.krylov_iterations += r.krylov_iterations;
    run.steps_converged += r.converged ? 1 : 0;
  }
  run.last = engine.state().functionals;
  return run;
}

TEST(KrylovNewton, SolvesTheSameStepsWithFewerFactorizations) {
  const int steps = 12;
  const BallRun direct = falling_ball(0, steps);
  const BallRun krylov = falling_ball(40, steps);
  EXPECT_EQ(direct.steps_converged, steps);
  EXPECT_EQ(krylov.steps_converged, steps);
  EXPECT_EQ(direct.krylov_iterations, 0);
  EXPECT_GT(krylov.krylov_iterations, 0);
  // Without GMRES every new Jacobian is factorized; with it, some are only solved with.
  EXPECT_EQ(direct.jacobian_assemblies, direct.factorizations);
  EXPECT_GT(krylov.jacobian_assemblies, krylov.factorizations);
  EXPECT_LT(krylov.factorizations, direct.factorizations)
      << "direct " << direct.factorizations << ", with GMRES " << krylov.factorizations << " + "
      << krylov.krylov_iterations << " GMRES iterations";
  // Both solve each step to Newton's tolerance (1e-8 of its start): the same motion.
  EXPECT_NEAR(krylov.last.centroid_y_m, direct.last.centroid_y_m, 1e-9);
  EXPECT_NEAR(krylov.last.mean_vy_mps, direct.last.mean_vy_mps, 1e-7);
  EXPECT_NEAR(krylov.last.mass_error, direct.last.mass_error, 1e-7);
}

}  // namespace
